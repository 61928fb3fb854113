#pragma once
// The viewer's camera: orbits a target point (yaw about the world's up axis,
// pitch above the horizon), pans the target in the view plane, zooms by
// distance. Z is up (gravity is -z in the scenarios). GL-free: matrices come
// from GLM and the renderer only reads them.

#include <glm/glm.hpp>

namespace mtcut::app::view {

// A ray from the eye through a pixel: origin and unit direction, world space.
struct Ray {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, -1.0};
};

class OrbitCamera {
 public:
  // Looks at the box [lo, hi] from the front-right, slightly above, with
  // the whole box in view; reset() returns to this pose.
  void frame(const glm::dvec3& lo, const glm::dvec3& hi);
  void reset();

  // Mouse drags by (dx, dy) pixels: orbit (0.3 degree per pixel); pan (the
  // target follows the cursor at the target's depth); zoom by scroll steps
  // (10% of the distance each, positive = closer).
  void orbit(double dx, double dy);
  void pan(double dx, double dy, int viewport_height);
  void zoom(double steps);

  glm::dmat4 view() const;
  glm::dmat4 projection(double aspect) const;
  glm::dvec3 eye() const;
  glm::dvec3 forward() const;  // unit, from the eye to the target
  const glm::dvec3& target() const { return target_; }
  double distance() const { return distance_; }
  double radius() const { return radius_; }

  // The ray through pixel (x, y) (top-left origin, as the mouse reports it)
  // of a width x height viewport.
  Ray ray_through(double x, double y, int width, int height) const;

 private:
  struct Pose {
    glm::dvec3 target{0.0};
    double distance = 1.0;
    double yaw = 0.0;    // radians about +z; 0 looks along +y
    double pitch = 0.0;  // radians above the horizon (the eye is above when > 0)
  };
  glm::dvec3 target_{0.0};
  double distance_ = 1.0;
  double yaw_ = 0.0;
  double pitch_ = 0.0;
  double fov_y_ = glm::radians(40.0);
  double radius_ = 0.5;  // of the framed box: sets near and far planes
  Pose home_;            // what frame() set
};

}  // namespace mtcut::app::view
