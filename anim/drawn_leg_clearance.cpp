#include "anim/drawn_leg_clearance.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "anim/joint_limits.hpp"
#include "anim/limb_clearance.hpp"
#include "anim/player_animation.hpp"
#include "anim/portable_math.hpp"

namespace mc::anim {
namespace {

// Below this clearance of the plain blend (angles only, before the
// clients' step) at a third or two thirds of the frame, the clients' step
// is run to see what they draw. Run on every frame, the check cost a third
// of the animation's instructions; with a 5 cm gate, or all five points,
// the figures are the same.
constexpr float kGateM = 0.025f;
// Half-way first: legs this far apart there are not checked further (10 cm
// let one more case through on each full game).
constexpr float kMidGateM = 0.12f;
// Legs whose every angle (and the pelvis's) turns less than this over the
// frame (deg) are not checked (5 gave the same figures).
constexpr float kStillDeg = 10.0f;
// How much further a turned leg may carry a foot over the grass (m a frame).
constexpr float kSlideSlackM = 0.02f;

PlayerPose pose_of(const DrawnRoot& r, std::span<const float> angles) {
  PlayerPose p;
  p.x = r.x;
  p.y = r.y;
  p.z = r.height;
  p.heading = r.heading;
  std::copy_n(angles.begin(), std::min(angles.size(), p.angles.size()), p.angles.begin());
  return p;
}

// The clients' blend (proto/SPEC.md 4.7 step 1): the root and every angle
// linearly, the heading the short way round.
PlayerPose blend_of(const PlayerPose& pa, const PlayerPose& pb, float t) {
  PlayerPose o = pa;
  o.x = pa.x + (pb.x - pa.x) * t;
  o.y = pa.y + (pb.y - pa.y) * t;
  o.z = pa.z + (pb.z - pa.z) * t;
  o.heading = pa.heading + std::remainder(pb.heading - pa.heading, 360.0f) * t;
  for (std::size_t k = 0; k < o.angles.size(); ++k) o.angles[k] = pa.angles[k] + (pb.angles[k] - pa.angles[k]) * t;
  return o;
}

float check_t(int n) { return static_cast<float>(n + 1) / static_cast<float>(kDrawnChecks + 1); }

// What the clients draw from `pa` to `pb`: the legs' least clearance (the
// frame's own included), and per leg its ankle's largest move in a third
// of the frame as a share of the pop bounds (over the grass and about the
// root; > 1 pops), and how far it moves over the grass while on it.
struct Drawn {
  float clearance = INFINITY;
  float pop[2] = {0, 0};
  float slide[2] = {0, 0};  // m over the grass while the sole is on it at both ends of a third
};
static_assert(kDrawnChecks == 5, "the thirds below are checks 1 and 3");
Drawn drawn_frame(const LegBlend& legs, const PlayerPose& pa, const PlayerPose& pb) {
  Drawn d;
  d.clearance = legs.clearance(pb);
  float low[2];
  glm::vec3 at[2] = {legs.ankle(pa, 0, &low[0]), legs.ankle(pa, 1, &low[1])}, root(pa.x, pa.z, pa.y);
  for (int n = 0; n < kDrawnChecks; ++n) {
    const float t = check_t(n);
    PlayerPose o = blend_of(pa, pb, t);
    legs.apply(pa, pb, t, o);
    d.clearance = std::min(d.clearance, legs.clearance(o));
    const bool third = n % 2 == 1 || n + 1 == kDrawnChecks;  // t = 1/3, 2/3, then the frame's end
    if (!third) continue;
    const PlayerPose& end = n + 1 == kDrawnChecks ? pb : o;
    const glm::vec3 r(end.x, end.z, end.y);
    for (int i = 0; i < 2; ++i) {
      float sole;
      const glm::vec3 to = legs.ankle(end, i, &sole);
      const glm::vec3 move = to - at[i];
      if (low[i] < LegBlend::kContactM && sole < LegBlend::kContactM) d.slide[i] += pm::hypot(move.x, move.z);
      low[i] = sole;
      d.pop[i] = std::max({d.pop[i], 3.0f * glm::length(move) / kDrawnPopM,
                           3.0f * glm::length(move - (r - root)) / kDrawnPopRelM});
      at[i] = to;
    }
    root = r;
  }
  return d;
}

}  // namespace

float drawn_leg_clearance(const LegBlend& legs, const PlayerPose& last, const DrawnRoot& now,
                          std::span<const float> a) {
  return drawn_frame(legs, last, pose_of(now, a)).clearance;
}

PlayerPose as_streamed(const proto::Quantizer& grid, const PlayerPose& pose) {
  PlayerPose o = pose;
  o.x = static_cast<float>(proto::Quantizer::position_q(pose.x) * proto::kPositionStepM);
  o.y = static_cast<float>(proto::Quantizer::position_q(pose.y) * proto::kPositionStepM);
  o.z = static_cast<float>(proto::Quantizer::position_q(pose.z) * proto::kPositionStepM);
  o.heading = proto::Quantizer::heading_value(proto::Quantizer::heading_q(pose.heading));
  for (int d = 0; d < grid.dof_count() && d < kMaxDof; ++d)
    o.angles[static_cast<std::size_t>(d)] = grid.angle_value(d, grid.angle_q(d, pose.angles[static_cast<std::size_t>(d)]));
  return o;
}

bool keep_legs_apart_drawn(const LegBlend& legs, const SkeletonDef& skel, const proto::Quantizer* grid,
                           const PlayerPose& last, std::span<const float> last_angles, const DrawnRoot& now,
                           const bool planted[2], std::span<float> a) {
  if (!legs.ready() || (planted[0] && planted[1])) return false;
  // Most frames need no more: legs that hardly turn (a player standing or
  // walking slowly) are drawn as they are at the frames, which keep apart
  // (limb_clearance.hpp); the others are gated by the plain blend (kGateM).
  float turn = 0;
  for (int d = dof::kPelvis; d < dof::kPelvis + 3; ++d)
    turn = std::max(turn, std::fabs(a[static_cast<std::size_t>(d)] - last.angles[static_cast<std::size_t>(d)]));
  for (int d = dof::kRHip; d < dof::kCount; ++d)
    turn = std::max(turn, std::fabs(a[static_cast<std::size_t>(d)] - last.angles[static_cast<std::size_t>(d)]));
  if (turn < kStillDeg) return false;
  PlayerPose pb = pose_of(now, a);
  if (legs.clearance(blend_of(last, pb, 0.5f)) >= kMidGateM) return false;
  float plain = INFINITY;
  for (const float t : {1.0f / 3.0f, 2.0f / 3.0f}) plain = std::min(plain, legs.clearance(blend_of(last, pb, t)));
  if (plain >= kGateM) return false;
  const PlayerPose pa = grid != nullptr ? as_streamed(*grid, last) : last;
  const Drawn before = drawn_frame(legs, pa, pb);
  if (before.clearance >= kDrawnApartM) return false;
  float best = before.clearance;
  std::array<float, dof::kCount> best_a{}, cand{};
  // The frame itself may come no closer than it was, or than the margin
  // (the next frame's blend starts from it).
  const float frame_floor = std::min(legs.clearance(pb), kDrawnApartM);
  // Leg `side`'s dof `k` (the hip's or the knee's) turned by `way`
  // kDrawnStepDeg at a time, until the blend clears or a bound stops it.
  auto turn_dof = [&](int side, std::size_t k, float way) {
    for (float turn = kDrawnStepDeg; turn <= kDrawnMostDeg + 1e-3f; turn += kDrawnStepDeg) {
      std::copy_n(a.begin(), dof::kCount, cand.begin());
      cand[k] += turn * way;
      clamp_to_limits(skel, cand);
      if (cand[k] == a[k]) return;  // at its limit
      // Each joint within its own speed limit: the hip's three dofs as one
      // rotation, the knee's one angle.
      const bool knee = k == static_cast<std::size_t>(dof::kRKnee) || k == static_cast<std::size_t>(dof::kLKnee);
      if (knee ? std::fabs(cand[k] - last_angles[k]) > kMaxLegStepDeg
               : hip_turning_too_fast(last_angles, cand, kMaxLegStepDeg + kSeparateAgainDeg, side) >= 0)
        return;
      std::copy_n(cand.begin(), dof::kCount, pb.angles.begin());
      if (legs.clearance(pb) < frame_floor) return;
      const Drawn d = drawn_frame(legs, pa, pb);
      // No ankle pops where there were none (nor worse ones), and no foot
      // on the grass carried over it further.
      for (int i = 0; i < 2; ++i)
        if (d.pop[i] > std::max(1.0f, before.pop[i]) || d.slide[i] > before.slide[i] + kSlideSlackM) return;
      if (d.clearance > best) {
        best = d.clearance;
        best_a = cand;
      }
      if (d.clearance >= kDrawnApartM) return;
    }
  };
  // A leg in the air swings forward or back (flexion), which carries its
  // thigh and foot past the other leg's rather than through them; turns
  // out (abduction) or, crossed over the other one, further across; or
  // about its own axis (the hip's rotation), which swings a foot's toe or
  // heel out of the other foot's way; or bends or straightens its knee,
  // which lifts or moves its foot past the other one (a turning step whose
  // swing crosses in front of the planted foot). With flexion added
  // (2026-11-29), legs too close at 60 Hz on the two full games went
  // 9 -> 2 player-frames, and with 2-degree steps (4 before) to 1.
  for (int side = 0; side < 2; ++side) {
    if (planted[side]) continue;
    const auto hip = static_cast<std::size_t>(side == 0 ? dof::kRHip : dof::kLHip);
    const float out = side == 0 ? -1.0f : 1.0f;  // the right abducts towards -X, the left towards +X
    for (const float way : {out, -out}) {
      turn_dof(side, hip, way);
      turn_dof(side, hip + 1, way);
      turn_dof(side, hip + 2, way);
    }
    const auto knee = static_cast<std::size_t>(side == 0 ? dof::kRKnee : dof::kLKnee);
    turn_dof(side, knee, 1.0f);
    turn_dof(side, knee, -1.0f);
  }
  if (best <= before.clearance) return false;
  std::copy_n(best_a.begin(), dof::kCount, a.begin());
  return true;
}

}  // namespace mc::anim
