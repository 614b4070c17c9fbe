#include "anim/drawn_leg_clearance.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "anim/body_frame.hpp"
#include "anim/grid_rounding.hpp"
#include "anim/ground_contact.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/joint_limits.hpp"
#include "anim/limb_clearance.hpp"
#include "anim/local_to_model_job.hpp"
#include "anim/player_animation.hpp"
#include "anim/portable_math.hpp"

namespace mc::anim {
namespace {

// Below this clearance of the plain blend (angles only, before the
// clients' step) at the check's own points (1/kDrawnSteps ... of the
// frame), the clients' step is run to see what they draw. Run on every frame, the check cost a third of
// the animation's instructions; with no gates at all the figures are the
// same, with 1 cm (and kMidGateM 8 cm) legs too close at 60 Hz went 56 ->
// 119 player-frames over eight phases of the display (anim/README.md).
constexpr float kGateM = 0.025f;
// Half-way first: legs this far apart there are not checked further (10 cm
// let one more case through on each full game).
constexpr float kMidGateM = 0.12f;
// Legs whose every angle (and the pelvis's) turns less than this over the
// frame (deg) are not checked (5 gave the same figures).
constexpr float kStillDeg = 10.0f;
// How much further a turned leg may carry a foot over the grass (m a frame).
constexpr float kSlideSlackM = 0.02f;
// A turned thigh keeps its own side's hand this far out (m, negative:
// outside), as keep_hands_off_thighs keeps it in the clients' blend.
constexpr float kHandOffM = -0.01f;
// The least clearance is searched for between two steps where either is
// closer than this (m): the nearest point may be half a step (1/12 of the
// frame) from them, and legs passing at 0.5 m a frame close 4 cm in that.
// Such a stretch is split in kSplits and drawn at the two points between
// (a third of a step apart, 1/18 of the frame), and then kRefineRounds of
// a golden-section search narrow the nearest point's two neighbours (1/9
// of the frame) to 1/420. Quarters of a step cleared the same player-frames
// for 1.7 % more of the animation's instructions.
constexpr float kRefineBelowM = 0.05f;
constexpr int kSplits = 3;
constexpr int kRefineRounds = 8;
// The drawn points whose feet's way (feet_way_turns) is kept: at most the
// first one, the five steps between the frames, two more in each of the
// six stretches and the golden-section search's ten (28).
constexpr std::size_t kMaxParted = 28;
// A stretch between two drawn points over which the feet's way turns more
// than kWayTurnDeg (feet_way_turns) is drawn at kTurnPoints - 1 points
// between them. 15 since the clients part the feet from each other's
// centre line (session 37): at 30, a turn of that way between 15 and 30
// deg hid the feet 1.2 cm inside each other at display phase 0.125 (game 2
// seq 332, right 3).
constexpr float kWayTurnDeg = 15.0f;
constexpr int kTurnPoints = 16;

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
  o.heading = pa.heading + remainder_360(pb.heading - pa.heading) * t;
  for (std::size_t k = 0; k < o.angles.size(); ++k) o.angles[k] = pa.angles[k] + (pb.angles[k] - pa.angles[k]) * t;
  return o;
}

float step_t(int n) { return static_cast<float>(n) / static_cast<float>(kDrawnSteps); }

// What the clients draw from `pa` to `pb`: the legs' least clearance over
// the whole frame (the frame's own included) and where in it (t), and per
// leg its ankle's largest move in a third of the frame, wherever the third
// starts, as a share of the pop bounds (over the grass and about the root;
// > 1 pops), and how far it moves over the grass while on it.
struct Drawn {
  float clearance = INFINITY;
  float at = 0.5f;
  bool beaten = false;  // stopped early: somewhere no clearer than `beat` (below)
  float pop[2] = {0, 0};
  float slide[2] = {0, 0};  // m over the grass while the sole is on it at both ends of a third
};
static_assert(kDrawnSteps % 3 == 0, "a third of the frame is a whole number of steps");

// Where the way the clients' step parts the feet turns fast between two
// neighbouring drawn points, the step may fail to hold them apart in a
// sliver between: as their centre lines pass each other the way swings
// through one in which the leg's turn, within its bounds, moves the foot
// too little (game 2 seq 11923, left 3: the way swung 75 deg from t =
// 0.196 to 0.222, and from 0.199 to 0.204 the feet were drawn up to 1.1
// cm inside each other). No search over the clearance finds so narrow a
// dip, so such a stretch is drawn at kTurnPoints points. `parted`: the
// points drawn (t, way), `draw(t, way)` draws another. Returns the least
// clearance found there (INFINITY when the way never turns that fast).
// With `beat`, it stops at the first point no clearer than that (`beaten`).
template <typename Draw>
Drawn feet_way_turns(const LegBlend& legs, Draw draw, std::pair<float, glm::vec3>* parted, std::size_t n,
                     float beat) {
  Drawn d;
  std::sort(parted, parted + n, [](const auto& p, const auto& q) { return p.first < q.first; });
  const float cos_turn = pm::cos(kWayTurnDeg * kDeg);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const glm::vec3 u = parted[i].second, v = parted[i + 1].second;
    const float lu = glm::length(u), lv = glm::length(v);
    if (lu <= 0.0f || lv <= 0.0f || glm::dot(u, v) >= cos_turn * lu * lv) continue;
    const float lo = parted[i].first, hi = parted[i + 1].first;
    glm::vec3 way;
    for (int k = 1; k < kTurnPoints; ++k) {
      const float t = lo + (hi - lo) * static_cast<float>(k) / kTurnPoints;
      const float c = legs.clearance(draw(t, way));
      if (c < d.clearance) {
        d.clearance = c;
        d.at = t;
      }
      if (c <= beat) {
        d.beaten = true;
        return d;
      }
    }
  }
  return d;
}
// With `beat`, the frame is drawn first at `first` (unless it is NaN), and
// drawing stops (`beaten`, the rest unset) as soon as the legs come no
// clearer than `beat` anywhere: a candidate turn that does not beat the
// best so far costs one drawing, not the frame's five and a search's
// twelve (every candidate drawn in full, at 1/24 steps, took the animation
// bench from 1.6 to 3.0 s a game). Beaten or not is what drawing the
// whole frame would say, as long as no point is NaN: the least clearance
// is no more than any point's, and the golden-section search below keeps
// the least it has seen (after a NaN it may drop it, so it stops on its own
// points only while it has seen none).
Drawn drawn_frame(const LegBlend& legs, const PlayerPose& pa, const PlayerPose& pb, float beat = -INFINITY,
                  float first = 0.5f) {
  // Each point drawn, with the way the clients' step parted the feet there
  // (LegBlend::apply's feet_way; kept for the first kMaxParted points).
  std::array<std::pair<float, glm::vec3>, kMaxParted> parted;
  std::size_t parted_n = 0;
  const LegBlend::Frames frames = legs.frames(pa, pb);  // the same at every point drawn
  auto drawn_way = [&](float t, glm::vec3& way) {
    PlayerPose o = blend_of(pa, pb, t);
    legs.apply(frames, t, o, &way);
    return o;
  };
  auto drawn_at = [&](float t) {
    glm::vec3 way;
    PlayerPose o = drawn_way(t, way);
    if (parted_n < parted.size()) parted[parted_n++] = {t, way};
    return o;
  };
  Drawn d;
  auto beaten = [&](float clearance, float t) {
    if (clearance > beat) return false;
    d.clearance = clearance;
    d.at = t;
    d.beaten = true;
    return true;
  };
  if (beat > -INFINITY && !std::isnan(first) && beaten(legs.clearance(drawn_at(first)), first)) return d;
  constexpr int kThird = kDrawnSteps / 3;
  std::array<float, kDrawnSteps + 1> clear{}, low[2]{};
  std::array<glm::vec3, kDrawnSteps + 1> at[2], root{};
  for (int n = 0; n <= kDrawnSteps; ++n) {
    const PlayerPose o = n == 0 ? pa : n == kDrawnSteps ? pb : drawn_at(step_t(n));
    clear[n] = n == 0 ? INFINITY : legs.clearance(o);  // the last frame was checked as it was made
    if (beaten(clear[n], step_t(n))) return d;
    root[n] = glm::vec3(o.x, o.z, o.y);
    for (int i = 0; i < 2; ++i) at[i][n] = legs.ankle(o, i, &low[i][n]);
  }
  // The least clearance between the steps: the legs pass each other fast
  // (a foot 0.5 m a frame), so the nearest step can be centimetres clearer
  // than the nearest point, which a display drawing at any other phase
  // shows. Every stretch between two steps where the legs come within
  // kRefineBelowM is drawn at thirds of a step, and a golden-section search
  // narrows in about the nearest of all. The curve is not one smooth dip:
  // the clients' step bends it, and the legs can come close twice in a
  // frame. Searched about the nearest step alone, the search settled in a
  // dip beside a deeper one (game 1 seq 2194 right 2: 1.0 cm found at t =
  // 0.465, the feet 3 cm through each other at 0.645), or never looked at
  // a dip two steps away (game 2 seq 4811 right 11: 1 cm found at 0.771,
  // -1.1 cm at 0.283).
  d.clearance = INFINITY;
  for (int n = 1; n <= kDrawnSteps; ++n)
    if (clear[n] < d.clearance) {
      d.clearance = clear[n];
      d.at = step_t(n);
    }
  if (d.clearance < kRefineBelowM) {
    for (int n = 1; n <= kDrawnSteps; ++n) {
      if (std::min(clear[n - 1], clear[n]) >= kRefineBelowM) continue;
      for (int q = 1; q < kSplits; ++q) {
        const float t = step_t(n - 1) + static_cast<float>(q) / (kSplits * kDrawnSteps);
        const float c = legs.clearance(drawn_at(t));
        if (beaten(c, t)) return d;
        if (c < d.clearance) {
          d.clearance = c;
          d.at = t;
        }
      }
    }
    constexpr float kGolden = 0.618034f, kSplit = 1.0f / (kSplits * kDrawnSteps);
    float lo = std::max(0.0f, d.at - kSplit), hi = std::min(1.0f, d.at + kSplit);
    float x1 = hi - kGolden * (hi - lo), x2 = lo + kGolden * (hi - lo);
    float f1 = legs.clearance(drawn_at(x1)), f2 = legs.clearance(drawn_at(x2));
    // Each round keeps the lesser of its two points, so the least of all
    // is one of the last two: a point no clearer than `beat` ends it
    // beaten (a NaN could be dropped, so not after one).
    bool keeps_least = !std::isnan(f1) && !std::isnan(f2);
    auto stop = [&](float f, float t) { return keeps_least && beaten(f, t); };
    if (stop(std::min(f1, f2), f1 < f2 ? x1 : x2)) return d;
    for (int k = 0; k < kRefineRounds; ++k) {
      float f = 0, t = 0;
      if (f1 < f2) {
        hi = x2, x2 = x1, f2 = f1;
        x1 = hi - kGolden * (hi - lo);
        f = f1 = legs.clearance(drawn_at(t = x1));
      } else {
        lo = x1, x1 = x2, f1 = f2;
        x2 = lo + kGolden * (hi - lo);
        f = f2 = legs.clearance(drawn_at(t = x2));
      }
      keeps_least = keeps_least && !std::isnan(f);
      if (stop(f, t)) return d;
    }
    if (std::min(f1, f2) < d.clearance) {
      d.clearance = std::min(f1, f2);
      d.at = f1 < f2 ? x1 : x2;
    }
    const Drawn through = feet_way_turns(legs, drawn_way, parted.data(), parted_n, beat);
    if (through.beaten) return through;
    if (through.clearance < d.clearance) {
      d.clearance = through.clearance;
      d.at = through.at;
    }
    if (beaten(d.clearance, d.at)) return d;
  }
  for (int i = 0; i < 2; ++i)
    for (int n = kThird; n <= kDrawnSteps; ++n) {
      const glm::vec3 move = at[i][n] - at[i][n - kThird];
      d.pop[i] = std::max({d.pop[i], 3.0f * glm::length(move) / kDrawnPopM,
                           3.0f * glm::length(move - (root[n] - root[n - kThird])) / kDrawnPopRelM});
      if (n % kThird == 0 && low[i][n - kThird] < LegBlend::kContactM && low[i][n] < LegBlend::kContactM)
        d.slide[i] += pm::hypot(move.x, move.z);
    }
  return d;
}

}  // namespace

float drawn_leg_clearance(const LegBlend& legs, const PlayerPose& last, const DrawnRoot& now,
                          std::span<const float> a) {
  return drawn_frame(legs, last, pose_of(now, a)).clearance;
}

bool drawn_leg_beaten(const LegBlend& legs, const PlayerPose& last, const DrawnRoot& now, std::span<const float> a,
                      float beat, float first) {
  return drawn_frame(legs, last, pose_of(now, a), beat, first).beaten;
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
                           const bool planted[2], std::span<float> a, bool turned) {
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
  // The plain blend's clearance reads its angles alone (LegBlend::clearance
  // poses the legs in the root's space): the root and the heading are not
  // blended for it (the heading's wrap is a library call, and the gate
  // blends 368,000 times on game 1: 0.4 % of the animation's instructions).
  PlayerPose plain_pose = last;
  auto plain_at = [&](float t) {
    for (std::size_t k = 0; k < plain_pose.angles.size(); ++k)
      plain_pose.angles[k] = last.angles[k] + (pb.angles[k] - last.angles[k]) * t;
    return legs.clearance(plain_pose);
  };
  // The gate decides on rough clearances (LegBlend::rough_clearance; the
  // exact ones were 8.9 % of the animation's instructions, and their new
  // angles crowded the sine table): only where a rough one is within
  // kRoughClearanceM of a bound, or unknown, is the exact one taken (3,654
  // of game 1's 330,602), so the gate lets through the frames it let through
  // with exact ones alone, and the frames are the same to the bit.
  enum class Side { Below, Above, Unsure };
  auto side_of = [](float rough, float bound) {
    if (!std::isfinite(rough)) return Side::Unsure;
    if (rough >= bound + LegBlend::kRoughClearanceM) return Side::Above;
    if (rough < bound - LegBlend::kRoughClearanceM) return Side::Below;
    return Side::Unsure;
  };
  auto rough_at = [&](float t) { return legs.rough_clearance(last.angles.data(), pb.angles.data(), t); };
  // The middle first: legs kMidGateM apart there are not checked further.
  const float rough_mid = rough_at(0.5f);
  float mid = NAN;  // exact, when taken
  switch (side_of(rough_mid, kMidGateM)) {
    case Side::Above: return false;
    case Side::Unsure:
      mid = plain_at(0.5f);
      if (mid >= kMidGateM) return false;
      break;
    case Side::Below: break;
  }
  // Then on to the drawing only if the plain blend comes closer than kGateM
  // at one of the steps (an exact NaN in the middle goes on, elsewhere it
  // counts for nothing, as std::min took them before).
  bool closer = false;
  bool unsure[kDrawnSteps] = {};
  for (int n = 1; n < kDrawnSteps && !closer; ++n) {
    const Side side = 2 * n == kDrawnSteps ? side_of(rough_mid, kGateM) : side_of(rough_at(step_t(n)), kGateM);
    closer = side == Side::Below;
    unsure[n] = side == Side::Unsure;
  }
  for (int n = 1; n < kDrawnSteps && !closer; ++n) {
    if (!unsure[n]) continue;
    if (2 * n == kDrawnSteps) {
      if (std::isnan(mid)) mid = plain_at(0.5f);
      closer = !(mid >= kGateM);
    } else {
      closer = plain_at(step_t(n)) < kGateM;
    }
  }
  if (!closer) return false;
  const PlayerPose pa = grid != nullptr ? as_streamed(*grid, last) : last;
  // A turn that clears is drawn once more as the stream will carry the
  // frame: rounded by the animator (grid_rounding.hpp, which may move a hip
  // 0.99 deg to keep an ankle in place) and then by the encoder. It counts
  // as clear only if that clears too: legs cleared unrounded by 5 mm came
  // back 1 cm inside (game 2 seq 13659). The turns are still searched
  // unrounded (searched rounded, the 4-degree steps lose their effect in
  // the rounding: legs too close at eight phases of the display 12 / 33 ->
  // 24 / 59 player-frames). A frame that needs no turn is drawn again only
  // when this check turned it before (`turned`: resting it on the grass
  // since may have changed its rounding); every frame drawn again cost
  // 5.5 % of the animation (anim/README.md).
  std::array<glm::mat4, kHumanJointCount> models{};
  // `beat`: a candidate turn, which is passed over when the frame as sent
  // comes no clearer than the best so far: drawing it stops there (the
  // clearance it returns is then no more than `beat`, not the least).
  auto as_sent = [&](Drawn d, const PlayerPose& p, float beat = -INFINITY) {
    if (grid == nullptr || d.beaten || d.clearance < kDrawnApartM) return d;
    PlayerPose q = p;
    LocalToModelJob fk{&skel, std::span<const float>(q.angles.data(), dof::kCount), glm::vec3(0, q.z, 0), models};
    fk.joint_mask = kLegJoints;
    if (fk.Run()) round_legs_to_grid(*grid, skel, models.data(), q);
    d.clearance = std::min(d.clearance, drawn_frame(legs, pa, as_streamed(*grid, q), beat, NAN).clearance);
    return d;
  };
  const Drawn before = turned ? as_sent(drawn_frame(legs, pa, pb), pb) : drawn_frame(legs, pa, pb);
  if (before.clearance >= kDrawnApartM) return false;
  float best = before.clearance, worst_at = before.at;
  std::array<float, dof::kCount> best_a{}, cand{};
  // The frame itself may come no closer than it was, or than the margin
  // (the next frame's blend starts from it).
  const float frame_floor = std::min(legs.clearance(pb), kDrawnApartM);
  float hand_before[2] = {NAN, NAN};  // hand_depth_in_thigh of `a`, per side, when first needed
  enum class Tried { Kept, Passed, Cleared, Refused, AtLimit };
  // Leg `side`'s dof `k` (the hip's or the knee's) turned by `turn` deg.
  auto try_turn = [&](int side, std::size_t k, float turn) {
    std::copy_n(a.begin(), dof::kCount, cand.begin());
    cand[k] += turn;
    clamp_to_limits(skel, cand);
    if (cand[k] == a[k]) return Tried::AtLimit;
    // Each joint within its own speed limit: the hip's three dofs as one
    // rotation, the knee's one angle.
    const bool knee = k == static_cast<std::size_t>(dof::kRKnee) || k == static_cast<std::size_t>(dof::kLKnee);
    if (knee ? std::fabs(cand[k] - last_angles[k]) > kMaxKneeStepDeg
             : hip_turning_too_fast(last_angles, cand, kMaxLegStepDeg + kSeparateAgainDeg, side) >= 0)
      return Tried::Refused;
    std::copy_n(cand.begin(), dof::kCount, pb.angles.begin());
    if (legs.clearance(pb) < frame_floor) return Tried::Refused;
    // A turn no clearer than the best so far is passed over (a larger one
    // may still be).
    Drawn d = drawn_frame(legs, pa, pb, best, worst_at);
    if (d.beaten) return Tried::Passed;
    // No ankle pops where there were none (nor worse ones), and no foot
    // on the grass carried over it further (before the frame is drawn as
    // sent: a turn refused here is refused whatever that shows).
    for (int i = 0; i < 2; ++i)
      if (d.pop[i] > std::max(1.0f, before.pop[i]) || d.slide[i] > before.slide[i] + kSlideSlackM)
        return Tried::Refused;
    // Cleared unrounded, but as sent no clearer than the best so far.
    d = as_sent(d, pb, best);
    if (d.clearance <= best) return Tried::Passed;
    // Nor a thigh turned into its own side's hand, which the arm was held
    // out of before this check (keep_hands_off_thighs; game 1 seq 2491, a
    // runner's hand 5.5 cm inside his thigh).
    if (std::isnan(hand_before[side])) hand_before[side] = hand_depth_in_thigh(skel, a, last_angles, side);
    if (hand_depth_in_thigh(skel, cand, last_angles, side) > std::max(kHandOffM, hand_before[side]))
      return Tried::Refused;
    best = d.clearance;
    worst_at = d.at;
    best_a = cand;
    return d.clearance >= kDrawnApartM ? Tried::Cleared : Tried::Kept;
  };
  // The same dof turned by `way` kDrawnStepDeg at a time, until the blend
  // clears or a bound stops it. A step refused (a joint too fast, the
  // frame's own legs closer, an ankle popping or a foot carried over the
  // grass) is tried once more at half its size, as the largest turn the
  // bounds allow is often between two steps: game 2 seq 496, a sprinter's
  // thigh past the planted one, 4 degrees out popped the ankle by 4 %, and
  // 2 degrees let the next try clear it (anim/README.md).
  auto turn_dof = [&](int side, std::size_t k, float way) {
    for (float turn = kDrawnStepDeg; turn <= kDrawnMostDeg + 1e-3f; turn += kDrawnStepDeg) {
      const Tried r = try_turn(side, k, turn * way);
      if (r == Tried::Refused) try_turn(side, k, (turn - 0.5f * kDrawnStepDeg) * way);
      if (r == Tried::Refused || r == Tried::Cleared || r == Tried::AtLimit) return;
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
  // 9 -> 2 player-frames, and with 2-degree steps (4 before) to 1, at the
  // five points the check then sampled. Checked over the whole frame, 4-
  // degree steps leave fewer at eight phases of the display than 2 (45
  // player-frames against 65) for two thirds of the drawings (anim/README.md).
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
