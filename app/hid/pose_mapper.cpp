#include "app/hid/pose_mapper.h"

#include <algorithm>
#include <cmath>

namespace mtcut::app::hid {
namespace {

constexpr double kMaxTilt = 1.4;  // rad; a pen is never flat on the tablet

bool is_tilt(AxisTarget t) { return t == AxisTarget::tilt_x || t == AxisTarget::tilt_y; }

}  // namespace

double normalise_centred(const FieldDef& field, std::int64_t raw) {
  const double lo = static_cast<double>(field.logical_min), hi = static_cast<double>(field.logical_max);
  return std::clamp((2.0 * static_cast<double>(raw) - (lo + hi)) / (hi - lo), -1.0, 1.0);
}

double normalise_unipolar(const FieldDef& field, std::int64_t raw) {
  const double lo = static_cast<double>(field.logical_min), hi = static_cast<double>(field.logical_max);
  return std::clamp((static_cast<double>(raw) - lo) / (hi - lo), 0.0, 1.0);
}

double apply_dead_zone(double u, double dead_zone) {
  const double a = std::abs(u);
  if (a <= dead_zone) return 0.0;
  return std::copysign((a - dead_zone) / (1.0 - dead_zone), u);
}

PoseMapper::PoseMapper(const Profile& profile)
    : profile_(&profile),
      value_(profile.fields.size(), 0.0),
      seen_(profile.fields.size(), false),
      position_(profile.mapping.home) {}

Eigen::Matrix<double, 8, 1> PoseMapper::targets() const {
  Eigen::Matrix<double, 8, 1> t = Eigen::Matrix<double, 8, 1>::Zero();
  for (const AxisDef& axis : profile_->mapping.axes)
    t[static_cast<int>(axis.target)] +=
        axis.gain * apply_dead_zone(value_[static_cast<std::size_t>(axis.field)], axis.dead_zone);
  return t;
}

void PoseMapper::advance(double dt) {
  const MappingDef& m = profile_->mapping;
  if (m.mode != PoseMode::integrate || dt <= 0) return;
  const auto t = targets();
  const Vec3 lo = m.home - m.workspace, hi = m.home + m.workspace;
  position_ = (position_ + dt * t.segment<3>(0)).cwiseMax(lo).cwiseMin(hi);
  const Vec3 omega = t.segment<3>(3);
  const double angle = omega.norm() * dt;
  if (angle > 0) {
    orientation_ = Eigen::Quaterniond(Eigen::AngleAxisd(angle, omega.normalized())) * orientation_;
    orientation_.normalize();
  }
}

void PoseMapper::set_field(int field, std::int64_t raw) {
  const MappingDef& m = profile_->mapping;
  const FieldDef& def = profile_->fields[static_cast<std::size_t>(field)];
  if (field == m.engage_field) {
    const bool pressed = raw != 0;
    if (m.engage_mode == EngageMode::hold) engaged_ = pressed;
    else if (pressed && !pressed_) engaged_ = !engaged_;
    pressed_ = pressed;
  }
  const auto f = static_cast<std::size_t>(field);
  const double u = field == m.depth_field ? normalise_unipolar(def, raw) : normalise_centred(def, raw);
  value_[f] = seen_[f] ? m.smoothing * value_[f] + (1.0 - m.smoothing) * u : u;
  seen_[f] = true;
}

void PoseMapper::release() {
  engaged_ = false;
  pressed_ = false;
  if (profile_->mapping.mode == PoseMode::integrate) {
    std::fill(value_.begin(), value_.end(), 0.0);
    std::fill(seen_.begin(), seen_.end(), false);
  }
}

sim::ScalpelPose PoseMapper::pose() const {
  const MappingDef& m = profile_->mapping;
  const auto t = targets();
  Vec3 p = position_;
  Eigen::Quaterniond r = orientation_;
  if (m.mode == PoseMode::absolute) {
    p = (m.home + t.segment<3>(0)).cwiseMax(m.home - m.workspace).cwiseMin(m.home + m.workspace);
    r = Eigen::AngleAxisd(t[5], Vec3::UnitZ()) * Eigen::AngleAxisd(t[4], Vec3::UnitY()) *
        Eigen::AngleAxisd(t[3], Vec3::UnitX());
  }
  Vec3 d = r * Vec3(0, 0, -1);  // base -> tip
  bool tilt = false;
  for (const AxisDef& axis : m.axes) tilt |= is_tilt(axis.target);
  if (tilt) {
    const double ax = std::clamp(t[6], -kMaxTilt, kMaxTilt), ay = std::clamp(t[7], -kMaxTilt, kMaxTilt);
    d = -Vec3(std::tan(ax), std::tan(ay), 1.0).normalized();
  }
  const double depth = m.depth_field >= 0 ? m.depth_max * value_[static_cast<std::size_t>(m.depth_field)] : 0.0;
  sim::ScalpelPose pose;
  pose.tip = p + depth * d;
  pose.base = pose.tip - m.blade_length * d;
  pose.engaged = engaged_;
  return pose;
}

}  // namespace mtcut::app::hid
