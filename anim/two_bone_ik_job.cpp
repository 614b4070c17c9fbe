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

namespace {

// Each job's arithmetic is what one job alone would do, in the same order;
// only the jobs' stages interleave (a stage for every job before the next).
template <int N>
void solve(const TwoBoneIKJob* const (&job)[N], bool (&ran)[N]) {
  float l1[N]{}, l2[N]{}, tx[N]{}, ty[N]{}, tz[N]{}, d[N]{}, k[N]{}, p0x[N]{}, p0y[N]{}, p1x[N]{}, p1y[N]{}, p1z[N]{},
      b[N]{}, qx[N]{}, qy[N]{};
  bool ok[N]{};
  for (int j = 0; j < N; ++j) {
    ran[j] = job[j]->Validate();
    if (!ran[j]) continue;
    l1[j] = job[j]->upper_length, l2[j] = job[j]->lower_length;
    tx[j] = job[j]->target[0], ty[j] = job[j]->target[1], tz[j] = job[j]->target[2];
    d[j] = std::sqrt(tx[j] * tx[j] + ty[j] * ty[j] + tz[j] * tz[j]);
    const float d_max = (l1[j] + l2[j]) * job[j]->soften;
    const float d_min = std::max(std::fabs(l1[j] - l2[j]), 1e-4f * (l1[j] + l2[j])) * 1.001f;
    ok[j] = true;
    if (d[j] < 1e-6f) {  // degenerate: no direction, reach straight down
      tx[j] = 0; ty[j] = -d_min; tz[j] = 0; d[j] = d_min;
      ok[j] = false;
    } else if (d[j] > d_max || d[j] < d_min) {
      const float c = std::clamp(d[j], d_min, d_max);
      tx[j] *= c / d[j]; ty[j] *= c / d[j]; tz[j] *= c / d[j]; d[j] = c;
      ok[j] = false;
    }
  }
  for (int j = 0; j < N; ++j) {
    if (!ran[j]) continue;
    // Law of cosines: |end - start|^2 = l1^2 + l2^2 + 2 l1 l2 cos(k).
    const float cos_k =
        std::clamp((d[j] * d[j] - l1[j] * l1[j] - l2[j] * l2[j]) / (2 * l1[j] * l2[j]), -1.0f, 1.0f);
    k[j] = job[j]->hinge_sign * pm::acos(cos_k);  // radians
  }
  for (int j = 0; j < N; ++j) {
    if (!ran[j]) continue;
    // End joint in the start joint's frame, before the start joint rotates.
    float sk = 0, ck = 1;
    pm::sincos(k[j], sk, ck);
    p0x[j] = l2[j] * sk;
    p0y[j] = -l1[j] - l2[j] * ck;
  }
  for (int j = 0; j < N; ++j) {
    if (!ran[j]) continue;
    // The twist (applied first, about Y) turns the hinge plane.
    float sc = 0, cc = 1;
    sincos_deg(job[j]->twist_deg, sc, cc);  // remembered: the same twist comes back as a leg is solved again
    p1x[j] = p0x[j] * cc, p1y[j] = p0y[j], p1z[j] = -p0x[j] * sc;
  }
  for (int j = 0; j < N; ++j) {
    if (!ran[j]) continue;
    // Rx(b) must bring the z component to tz: p1z cos b + p1y sin b = tz.
    // Written as R cos(b + psi) with R = |(p1y, p1z)|, psi = atan2(-p1y, p1z);
    // the root near b = 0 is the one for a limb hanging down.
    const float r = std::sqrt(p1y[j] * p1y[j] + p1z[j] * p1z[j]);
    b[j] = 0;
    if (r > 1e-6f) {
      const float ratio = tz[j] / r;
      if (ratio > 1.0f || ratio < -1.0f) ok[j] = false;
      b[j] = pm::acos(std::clamp(ratio, -1.0f, 1.0f)) - pm::atan2(-p1y[j], p1z[j]);
    }
  }
  for (int j = 0; j < N; ++j) {
    if (!ran[j]) continue;
    float sb = 0, cb = 1;
    pm::sincos(b[j], sb, cb);
    qx[j] = p1x[j], qy[j] = p1y[j] * cb - p1z[j] * sb;
  }
  for (int j = 0; j < N; ++j) {
    if (!ran[j]) continue;
    // Rz(a) turns (qx, qy) onto (tx, ty); both have the same length.
    float a = pm::atan2(ty[j], tx[j]) - pm::atan2(qy[j], qx[j]);
    constexpr float kPi = 3.14159265358979f;
    while (a > kPi) a -= 2 * kPi;
    while (a < -kPi) a += 2 * kPi;
    while (b[j] > kPi) b[j] -= 2 * kPi;
    while (b[j] < -kPi) b[j] += 2 * kPi;
    job[j]->start_zxy[0] = a * kRadToDeg;
    job[j]->start_zxy[1] = b[j] * kRadToDeg;
    job[j]->start_zxy[2] = job[j]->twist_deg;
    *job[j]->hinge_z = k[j] * kRadToDeg;
    if (job[j]->reached != nullptr) *job[j]->reached = ok[j];
  }
}

}  // namespace

bool TwoBoneIKJob::Run() const {
  const TwoBoneIKJob* const job[1] = {this};
  bool ran[1];
  solve(job, ran);
  return ran[0];
}

void run_both(const TwoBoneIKJob& first, const TwoBoneIKJob& second, bool ran[2]) {
  const TwoBoneIKJob* const job[2] = {&first, &second};
  bool both[2];
  solve(job, both);
  ran[0] = both[0];
  ran[1] = both[1];
}

}  // namespace mc::anim
