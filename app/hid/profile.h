#pragma once
// A HID device profile: which devices it fits, where each value sits in the
// device's input reports, and how those values move the scalpel. Profiles are
// plain data read from config/hid/*.toml (profile_file.h); the decoder
// (decoder.h) is the only code that interprets them.
//
// Why a data profile rather than code per device: HID reports are
// self-describing only through a report descriptor that vendors get wrong
// often enough; a short, checked table of byte offsets, bit sizes and ranges
// is what a user can read off `mtcut hid monitor` and a descriptor dump, and
// it keeps the decoder one pure function for every device.

#include <cstdint>
#include <string>
#include <vector>

#include "engine/predicates.h"

namespace mtcut::app::hid {

using engine::Vec3;

// One value in a report: a little-endian bit field.
struct FieldDef {
  std::string name;            // unique in the profile; the mapping refers to it
  int byte = 0;                // first byte, counted in the report as read (byte 0 is the report id when ids are used)
  int bit = 0;                 // first bit within that byte, 0..7
  int bits = 8;                // size, 1..32
  bool is_signed = false;      // two's complement
  std::int64_t logical_min = 0;    // the device's valid range; a report with a value outside is rejected
  std::int64_t logical_max = 255;
};

// One input report the device sends.
struct ReportDef {
  int id = 0;                  // report id 1..255; 0 when the device does not number its reports
  std::vector<int> fields;     // indices into Profile::fields
  int size = 0;                // bytes a report must have to hold all its fields
};

// Which devices a profile fits; every criterion given must hold.
struct MatchDef {
  std::vector<int> vendor_ids;   // empty: any vendor
  std::vector<int> product_ids;  // empty: any product
  int usage_page = -1;           // -1: any
  std::vector<int> usages;       // empty: any usage in the page
};

// A rate (integrate) or a position (absolute) per full deflection.
enum class PoseMode { integrate, absolute };

// What an axis drives: translation, rotation about a world axis, or pen tilt.
enum class AxisTarget { x, y, z, rx, ry, rz, tilt_x, tilt_y };

// hold: engaged while pressed; toggle: each press flips it.
enum class EngageMode { hold, toggle };

// One device axis driving one degree of freedom of the scalpel.
struct AxisDef {
  int field = -1;         // index into Profile::fields
  AxisTarget target = AxisTarget::x;
  // integrate: m/s or rad/s at full deflection; absolute: m or rad at full deflection.
  double gain = 0;
  double dead_zone = 0;   // fraction of the half range, [0, 1): values inside read as centred
};

// How decoded values become a ScalpelPose. The pose is a point P (the tip
// at zero depth), an orientation R (blade along -z when R = I), a blade
// length and a depth: tip = P + d * depth, base = tip - d * blade_length,
// with d = R * (0, 0, -1) (or the pen's axis when tilt is mapped).
struct MappingDef {
  PoseMode mode = PoseMode::integrate;
  std::vector<AxisDef> axes;
  Vec3 home = Vec3(0.0, 0.0, 0.06);         // P at start (integrate) or when every axis is centred (absolute), m
  Vec3 workspace = Vec3(0.15, 0.15, 0.15);  // half extents of the box around home that P is kept in, m
  double blade_length = 0.1;                // m
  int depth_field = -1;                     // pressure field pushing the tip along d (-1: none)
  double depth_max = 0;                     // depth at full pressure, m
  int engage_field = -1;                    // button or tip switch (-1: never engaged)
  EngageMode engage_mode = EngageMode::hold;
  double smoothing = 0;                     // exponential smoothing of axes per report, [0, 1); 0 = none
  double max_dt = 0.1;                      // longest gap integrated between two reports, s
};

struct Profile {
  std::string name;         // the file's stem
  std::string file;         // where it was read from
  std::string description;
  MatchDef match;
  std::vector<FieldDef> fields;
  std::vector<ReportDef> reports;
  MappingDef mapping;
};

}  // namespace mtcut::app::hid
