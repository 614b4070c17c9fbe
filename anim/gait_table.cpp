#include "anim/gait_table.hpp"

#include <array>
#include <cmath>

namespace mc::anim {
namespace {

// Keys 0-9: the right step (right touch-down at 0 m); keys 10-19: the left
// step, its mirror. Pelvis twist and arm swing follow the legs a half cycle
// apart; the walking pelvis is highest at mid-stance, the running one lowest.
constexpr std::array<GaitKey, 20> kKeys{{
    //  gain    walk    run     twist   roll    torso   r_arm   l_arm
    {0.000f, -1.000f, -0.063f, 1.000f, 0.000f, -1.000f, -1.000f, 1.000f},
    {0.140f, -0.909f, -0.472f, 0.977f, 0.208f, -0.977f, -0.977f, 0.977f},
    {0.300f, -0.606f, -0.832f, 0.896f, 0.398f, -0.896f, -0.896f, 0.896f},
    {0.480f, -0.099f, -0.999f, 0.741f, 0.498f, -0.741f, -0.741f, 0.741f},
    {0.680f, 0.491f, -0.839f, 0.504f, 0.436f, -0.504f, -0.504f, 0.504f},
    {0.880f, 0.903f, -0.372f, 0.220f, 0.215f, -0.220f, -0.220f, 0.220f},
    {1.080f, 0.986f, 0.229f, -0.084f, -0.084f, 0.084f, 0.084f, -0.084f},
    {1.300f, 0.665f, 0.787f, -0.409f, -0.373f, 0.409f, 0.409f, -0.409f},
    {1.540f, -0.008f, 0.998f, -0.710f, -0.500f, 0.710f, 0.710f, -0.710f},
    {1.800f, -0.721f, 0.647f, -0.928f, -0.347f, 0.928f, 0.928f, -0.928f},
    {2.050f, -1.000f, -0.063f, -1.000f, 0.000f, 1.000f, 1.000f, -1.000f},
    {2.190f, -0.909f, -0.472f, -0.977f, -0.208f, 0.977f, 0.977f, -0.977f},
    {2.350f, -0.606f, -0.832f, -0.896f, -0.398f, 0.896f, 0.896f, -0.896f},
    {2.530f, -0.099f, -0.999f, -0.741f, -0.498f, 0.741f, 0.741f, -0.741f},
    {2.730f, 0.491f, -0.839f, -0.504f, -0.436f, 0.504f, 0.504f, -0.504f},
    {2.930f, 0.903f, -0.372f, -0.220f, -0.215f, 0.220f, 0.220f, -0.220f},
    {3.130f, 0.986f, 0.229f, 0.084f, 0.084f, -0.084f, -0.084f, 0.084f},
    {3.350f, 0.665f, 0.787f, 0.409f, 0.373f, -0.409f, -0.409f, 0.409f},
    {3.590f, -0.008f, 0.998f, 0.710f, 0.500f, -0.710f, -0.710f, 0.710f},
    {3.850f, -0.721f, 0.647f, 0.928f, 0.347f, -0.928f, -0.928f, 0.928f},
}};

float wrap_cycle(float p) {
  p = std::fmod(p, kReferenceCycleM);
  if (p < 0) p += kReferenceCycleM;
  if (p >= kReferenceCycleM) p = 0;  // fmod rounding of values just below a multiple
  return p;
}

}  // namespace

std::span<const GaitKey> gait_keys() { return kKeys; }

float advance_posture(float posture_m, float distance_m, float cycle_m) {
  if (!(cycle_m > 0)) return wrap_cycle(posture_m);
  return wrap_cycle(posture_m + distance_m * (kReferenceCycleM / cycle_m));
}

bool SampleGaitJob::Validate() const {
  if (output == nullptr || keys.size() < 2) return false;
  if (keys[0].gain_m < 0) return false;
  for (std::size_t i = 1; i < keys.size(); ++i)
    if (!(keys[i].gain_m > keys[i - 1].gain_m)) return false;
  return keys.back().gain_m < kReferenceCycleM;
}

bool SampleGaitJob::Run() const {
  if (!Validate()) return false;
  const float p = wrap_cycle(posture_m);
  const std::size_t n = keys.size();
  // f- is the last key at or before p; before key 0 it is the last key of
  // the previous cycle.
  std::size_t lo = n - 1;
  for (std::size_t i = 0; i < n; ++i) {
    if (keys[i].gain_m <= p) lo = i;
    else break;
  }
  const std::size_t hi = (lo + 1) % n;
  float g_lo = keys[lo].gain_m, g_hi = keys[hi].gain_m, q = p;
  if (hi == 0) g_hi += kReferenceCycleM;             // wrap from the last key to key 0
  if (q < g_lo) q += kReferenceCycleM;               // p before key 0
  const float w = (q - g_lo) / (g_hi - g_lo);
  const GaitKey& a = keys[lo];
  const GaitKey& b = keys[hi];
  auto mix = [w](float x, float y) { return x + (y - x) * w; };
  GaitSample& o = *output;
  o.bob_walk = mix(a.bob_walk, b.bob_walk);
  o.bob_run = mix(a.bob_run, b.bob_run);
  o.pelvis_twist = mix(a.pelvis_twist, b.pelvis_twist);
  o.pelvis_roll = mix(a.pelvis_roll, b.pelvis_roll);
  o.torso_twist = mix(a.torso_twist, b.torso_twist);
  o.r_arm = mix(a.r_arm, b.r_arm);
  o.l_arm = mix(a.l_arm, b.l_arm);
  if (key_before != nullptr) *key_before = static_cast<int>(lo);
  if (weight_after != nullptr) *weight_after = w;
  return true;
}

}  // namespace mc::anim
