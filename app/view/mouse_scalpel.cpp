#include "app/view/mouse_scalpel.h"

#include <cmath>

namespace mtcut::app::view {

bool MouseScalpel::press(const Ray& ray, const std::optional<SurfaceHit>& hit) {
  if (!hit) return false;
  active_ = true;
  frames_ = 0;
  plane_point_ = hit->point;
  plane_normal_ = ray.direction;
  place(hit->point, ray.direction);
  return true;
}

void MouseScalpel::drag(const Ray& ray) {
  if (!active_) return;
  const double facing = glm::dot(ray.direction, plane_normal_);
  if (std::abs(facing) < 1e-6) return;  // the ray runs along the plane: keep the blade
  const double t = glm::dot(plane_point_ - ray.origin, plane_normal_) / facing;
  if (!(t > 0.0)) return;  // the plane is behind the eye
  place(ray.origin + t * ray.direction, ray.direction);
}

sim::ScalpelPose MouseScalpel::take_pose() {
  sim::ScalpelPose pose = pose_;
  pose.engaged = frames_ > 0;
  ++frames_;
  return pose;
}

void MouseScalpel::place(const glm::dvec3& entry, const glm::dvec3& direction) {
  const glm::dvec3 base = entry - def_.lift * direction;
  const glm::dvec3 tip = entry + def_.depth * direction;
  pose_.base = engine::Vec3(base.x, base.y, base.z);
  pose_.tip = engine::Vec3(tip.x, tip.y, tip.z);
}

}  // namespace mtcut::app::view
