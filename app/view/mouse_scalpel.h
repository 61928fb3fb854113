#pragma once
// The mouse as scalpel. A stroke starts on the surface point under the
// cursor: the blade lies along the view ray through it, from `lift` in
// front of the surface to `depth` into the tissue. While the mouse drags,
// the entry point follows the cursor in the plane through the first point
// facing the camera (a drag moves the blade sideways, never deeper), the
// blade staying along the current view ray. The blade is engaged from the
// second frame of the stroke on: the first frame only places it, so the
// World never sweeps from wherever the blade was before the stroke.

#include <optional>

#include <glm/glm.hpp>

#include "app/view/orbit_camera.h"
#include "app/view/ray_pick.h"
#include "sim/scalpel.h"

namespace mtcut::app::view {

struct MouseScalpelDef {
  double depth = 0.03;  // m of blade inside the tissue
  double lift = 0.01;   // m of blade in front of the surface
};

class MouseScalpel {
 public:
  explicit MouseScalpel(MouseScalpelDef def = {}) : def_(def) {}

  // Starts a stroke where `ray` meets the surface; false (no stroke) when it misses.
  bool press(const Ray& ray, const std::optional<SurfaceHit>& hit);
  // Moves the blade to the cursor's new ray (no-op without a stroke).
  void drag(const Ray& ray);
  void release() { active_ = false; }
  bool active() const { return active_; }

  // The pose for the next frame (engaged from the stroke's second frame);
  // counts the frame. Only meaningful while active().
  sim::ScalpelPose take_pose();

  MouseScalpelDef& def() { return def_; }

 private:
  void place(const glm::dvec3& entry, const glm::dvec3& direction);

  MouseScalpelDef def_;
  bool active_ = false;
  int frames_ = 0;                 // frames taken in this stroke
  glm::dvec3 plane_point_{0.0};    // the first entry point
  glm::dvec3 plane_normal_{0.0};   // the first ray's direction
  sim::ScalpelPose pose_;
};

}  // namespace mtcut::app::view
