#include "anim/two_bone_ik_job.hpp"

#include <algorithm>
#include <cmath>

#include "anim/portable_math.hpp"
#include "anim/sincos_deg.hpp"

namespace mc::anim {
namespace {
constexpr float kRadToDeg = 57.29577951308232f;
}  // namespace

bool TwoBoneIKJob::Validate() const {
  return upper_length > 0 && lower_length > 0 && start_zxy != nullptr && hinge_z != nullptr &&
         soften > 0 && soften <= 1 && std::isfinite(target[0]) && std::isfinite(target[1]) &&
         std::isfinite(target[2]);
}

bool TwoBoneIKJob::Run() const {
  if (!Validate()) return false;
  const float l1 = upper_length, l2 = lower_length;
  float tx = target[0], ty = target[1], tz = target[2];
  float d = std::sqrt(tx * tx + ty * ty + tz * tz);
  const float d_max = (l1 + l2) * soften;
  const float d_min = std::max(std::fabs(l1 - l2), 1e-4f * (l1 + l2)) * 1.001f;
  bool ok = true;
  if (d < 1e-6f) {  // degenerate: no direction, reach straight down
    tx = 0; ty = -d_min; tz = 0; d = d_min;
    ok = false;
  } else if (d > d_max || d < d_min) {
    const float c = std::clamp(d, d_min, d_max);
    tx *= c / d; ty *= c / d; tz *= c / d; d = c;
    ok = false;
  }
  // Law of cosines: |end - start|^2 = l1^2 + l2^2 + 2 l1 l2 cos(k).
  const float cos_k = std::clamp((d * d - l1 * l1 - l2 * l2) / (2 * l1 * l2), -1.0f, 1.0f);
  const float k = hinge_sign * pm::acos(cos_k);  // radians
  // End joint in the start joint's frame, before the start joint rotates.
  float sk = 0, ck = 1;
  pm::sincos(k, sk, ck);
  const float p0x = l2 * sk;
  const float p0y = -l1 - l2 * ck;
  // The twist (applied first, about Y) turns the hinge plane.
  float sc = 0, cc = 1;
  sincos_deg(twist_deg, sc, cc);  // remembered: the same twist comes back as a leg is solved again
  const float p1x = p0x * cc, p1y = p0y, p1z = -p0x * sc;
  // Rx(b) must bring the z component to tz: p1z cos b + p1y sin b = tz.
  // Written as R cos(b + psi) with R = |(p1y, p1z)|, psi = atan2(-p1y, p1z);
  // the root near b = 0 is the one for a limb hanging down.
  const float r = std::sqrt(p1y * p1y + p1z * p1z);
  float b = 0;
  if (r > 1e-6f) {
    const float ratio = tz / r;
    if (ratio > 1.0f || ratio < -1.0f) ok = false;
    b = pm::acos(std::clamp(ratio, -1.0f, 1.0f)) - pm::atan2(-p1y, p1z);
  }
  float sb = 0, cb = 1;
  pm::sincos(b, sb, cb);
  const float qx = p1x, qy = p1y * cb - p1z * sb;
  // Rz(a) turns (qx, qy) onto (tx, ty); both have the same length.
  float a = pm::atan2(ty, tx) - pm::atan2(qy, qx);
  constexpr float kPi = 3.14159265358979f;
  while (a > kPi) a -= 2 * kPi;
  while (a < -kPi) a += 2 * kPi;
  while (b > kPi) b -= 2 * kPi;
  while (b < -kPi) b += 2 * kPi;
  start_zxy[0] = a * kRadToDeg;
  start_zxy[1] = b * kRadToDeg;
  start_zxy[2] = twist_deg;
  *hinge_z = k * kRadToDeg;
  if (reached != nullptr) *reached = ok;
  return true;
}

}  // namespace mc::anim
