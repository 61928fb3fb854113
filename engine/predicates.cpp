#include "engine/predicates.h"

#include <tetgen.h>

namespace mtcut::engine {
namespace {

// exactinit must run once before orient3d; a function-local static makes that
// thread-safe and free of static initialisation order problems.
void ensure_exactinit() {
  static const bool initialised = [] {
    // verbose, noexact, nofilter, maxx, maxy, maxz: the bounding box only
    // tunes static filters; a unit box keeps them conservative.
    exactinit(0, 0, 0, 1.0, 1.0, 1.0);
    return true;
  }();
  (void)initialised;
}

}  // namespace

double orient3d_value(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  ensure_exactinit();
  // TetGen's orient3d(a, b, c, d) is positive when d is below (a, b, c), i.e.
  // it equals det[a-d, b-d, c-d] = -det[b-a, c-a, d-a]. Negate for our convention.
  Vec3 pa = a, pb = b, pc = c, pd = d;
  return -::orient3d(pa.data(), pb.data(), pc.data(), pd.data());
}

int orient3d_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double v = orient3d_value(a, b, c, d);
  return (v > 0) - (v < 0);
}

}  // namespace mtcut::engine
