#include "app/view/orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace mtcut::app::view {
namespace {

constexpr double kMaxPitch = glm::radians(89.0);

}  // namespace

void OrbitCamera::frame(const glm::dvec3& lo, const glm::dvec3& hi) {
  radius_ = std::max(0.5 * glm::length(hi - lo), 1e-3);
  home_.target = 0.5 * (lo + hi);
  home_.distance = 1.15 * radius_ / std::sin(0.5 * fov_y_);
  home_.yaw = glm::radians(30.0);
  home_.pitch = glm::radians(35.0);
  reset();
}

void OrbitCamera::reset() {
  target_ = home_.target;
  distance_ = home_.distance;
  yaw_ = home_.yaw;
  pitch_ = home_.pitch;
}

void OrbitCamera::orbit(double dx, double dy) {
  const double per_pixel = glm::radians(0.3);
  yaw_ -= dx * per_pixel;
  pitch_ = std::clamp(pitch_ + dy * per_pixel, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(double dx, double dy, int viewport_height) {
  // World length of one pixel at the target's depth.
  const double per_pixel = 2.0 * distance_ * std::tan(0.5 * fov_y_) / std::max(viewport_height, 1);
  const glm::dvec3 f = forward();
  const glm::dvec3 right = glm::normalize(glm::cross(f, glm::dvec3(0, 0, 1)));
  const glm::dvec3 up = glm::cross(right, f);
  target_ += (-dx * right + dy * up) * per_pixel;
}

void OrbitCamera::zoom(double steps) {
  distance_ = std::clamp(distance_ * std::pow(0.9, steps), 0.02 * radius_, 50.0 * radius_);
}

glm::dvec3 OrbitCamera::forward() const {
  // yaw 0 looks along +y; the eye sits behind the target along -forward.
  return {-std::sin(yaw_) * std::cos(pitch_), std::cos(yaw_) * std::cos(pitch_), -std::sin(pitch_)};
}

glm::dvec3 OrbitCamera::eye() const { return target_ - distance_ * forward(); }

glm::dmat4 OrbitCamera::view() const { return glm::lookAt(eye(), target_, glm::dvec3(0, 0, 1)); }

glm::dmat4 OrbitCamera::projection(double aspect) const {
  const double near_plane = std::max(distance_ - 20.0 * radius_, 0.01 * radius_);
  const double far_plane = distance_ + 20.0 * radius_;
  return glm::perspective(fov_y_, std::max(aspect, 1e-3), near_plane, far_plane);
}

Ray OrbitCamera::ray_through(double x, double y, int width, int height) const {
  const glm::dvec4 viewport(0, 0, std::max(width, 1), std::max(height, 1));
  const double aspect = viewport[2] / viewport[3];
  const glm::dvec3 window(x, viewport[3] - y, 0.0);  // GL's window origin is bottom-left
  const glm::dvec3 near_point = glm::unProject(window, view(), projection(aspect), viewport);
  const glm::dvec3 far_point =
      glm::unProject(glm::dvec3(window.x, window.y, 1.0), view(), projection(aspect), viewport);
  return {eye(), glm::normalize(far_point - near_point)};
}

}  // namespace mtcut::app::view
