#pragma once
// Field values -> scalpel pose, following a profile's mapping: a 6-DOF
// device's deflection is a velocity integrated over time, a tablet's position
// is the pose itself. Pure state, no clock: the caller passes time steps.

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "app/hid/profile.h"
#include "sim/scalpel.h"

namespace mtcut::app::hid {

class PoseMapper {
 public:
  // `profile` must outlive the mapper.
  explicit PoseMapper(const Profile& profile);

  // Integrates the current velocities over dt seconds (integrate mode; no-op otherwise).
  void advance(double dt);
  // A new raw value of field `field` (already checked against its logical range).
  void set_field(int field, std::int64_t raw);
  // The device went away: blade disengaged, a 6-DOF device at rest; the pose holds.
  void release();

  sim::ScalpelPose pose() const;

 private:
  // The axes' summed, dead-zoned contribution to each target (x..tilt_y).
  Eigen::Matrix<double, 8, 1> targets() const;

  const Profile* profile_;
  std::vector<double> value_;  // (fields) normalised, smoothed: [-1, 1] for axes, [0, 1] for depth
  std::vector<bool> seen_;     // (fields) a value has arrived since start or release
  Vec3 position_;              // P, m
  Eigen::Quaterniond orientation_ = Eigen::Quaterniond::Identity();  // integrate mode's R
  bool pressed_ = false;       // engage control's last state
  bool engaged_ = false;
};

// `raw` in [min, max] mapped to [-1, 1] (centre 0).
double normalise_centred(const FieldDef& field, std::int64_t raw);
// `raw` in [min, max] mapped to [0, 1].
double normalise_unipolar(const FieldDef& field, std::int64_t raw);
// 0 inside the dead zone, rescaled to reach +-1 at the ends outside it.
double apply_dead_zone(double u, double dead_zone);

}  // namespace mtcut::app::hid
