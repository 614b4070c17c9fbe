#include "anim/limb_clearance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "anim/body_frame.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/joint_limits.hpp"
#include "anim/local_to_model_job.hpp"
#include "anim/player_animation.hpp"
#include "anim/segment_distance.hpp"

namespace mc::anim {
namespace {

const std::string kYzx = "yzx", kZxy = "zxy", kZ = "z", kZx = "zx";
// Halvings of a turn-out too fast in full: to 1/64 of it (at most 0.4 deg
// of a turn-out of at most 25 deg).
constexpr int kTurnOutBisections = 6;

}  // namespace

float box_distance(const Segment& seg, const glm::vec3& p, glm::vec3* towards) {
  const glm::vec3 c(seg.center[0], seg.center[1], seg.center[2]);
  const glm::vec3 h(0.5f * seg.size[0], 0.5f * seg.size[1], 0.5f * seg.size[2]);
  const glm::vec3 d = p - c;
  const glm::vec3 q = glm::abs(d) - h;
  const glm::vec3 out = glm::max(q, glm::vec3(0.0f));
  const float outside = std::sqrt(glm::dot(out, out));
  const float inside = std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
  if (towards != nullptr) {
    // From the box's nearest surface point towards p.
    glm::vec3 n(0.0f);
    if (outside > 1e-6f) {
      for (int i = 0; i < 3; ++i) n[i] = q[i] > 0 ? (d[i] > 0 ? q[i] : -q[i]) : 0.0f;
      n /= outside;
    } else {
      const int i = q.x >= q.y && q.x >= q.z ? 0 : q.y >= q.z ? 1 : 2;
      n[i] = d[i] >= 0 ? 1.0f : -1.0f;
    }
    *towards = n;
  }
  return outside + inside;
}

namespace {

constexpr std::uint32_t kHandJoints = (1u << kPelvis) | (1u << kTorso) | (1u << kRUpperArm) | (1u << kRLowerArm) |
                                      (1u << kRHand) | (1u << kLUpperArm) | (1u << kLLowerArm) | (1u << kLHand) |
                                      (1u << kRThigh) | (1u << kLThigh);

// One side's hand and thigh with what they hang from.
constexpr std::uint32_t kSideJoints[2] = {
    (1u << kPelvis) | (1u << kTorso) | (1u << kRUpperArm) | (1u << kRLowerArm) | (1u << kRHand) | (1u << kRThigh),
    (1u << kPelvis) | (1u << kTorso) | (1u << kLUpperArm) | (1u << kLLowerArm) | (1u << kLHand) | (1u << kLThigh)};

bool pose_hands(const SkeletonDef& skel, std::span<const float> a, std::array<glm::mat4, kHumanJointCount>& m,
                std::uint32_t mask = kHandJoints) {
  LocalToModelJob fk{&skel, a, glm::vec3(0.0f, 1.0f, 0.0f), m};
  fk.joint_mask = mask;
  return fk.Run();
}

// The largest change (deg) of one side's hip or shoulder dofs from `last`
// to `a`. Below kBlendTurnDeg the blend is not posed: on both full games
// the hands inside a thigh at 60 Hz were 0 / 0 with that gate, as without.
float side_turn(std::span<const float> last, std::span<const float> a, int side) {
  float most = 0;
  for (int j : {side == 0 ? dof::kRHip : dof::kLHip, side == 0 ? dof::kRShoulder : dof::kLShoulder})
    for (int d = 0; d < 3; ++d) {
      const auto k = static_cast<std::size_t>(j + d);
      most = std::max(most, std::fabs(a[k] - last[k]));
    }
  return most;
}

// How deep (m) the hand of `side` (0 right) is in its own thigh's box in
// the posed `m`: > 0 inside, < 0 its distance outside, or `clear` when it
// is surely further out than `clear` (the box tests below).
float hand_in_thigh(const SkeletonDef& skel, const std::array<glm::mat4, kHumanJointCount>& m, int side, float clear) {
  const int hand = side == 0 ? kRHand : kLHand, thigh = side == 0 ? kRThigh : kLThigh;
  const Segment& hs = skel.joints[static_cast<std::size_t>(hand)].segment;
  const Segment& ts = skel.joints[static_cast<std::size_t>(thigh)].segment;
  const glm::vec3 hc(hs.center[0], hs.center[1], hs.center[2]);
  const glm::vec3 hh(0.5f * hs.size[0], 0.5f * hs.size[1], 0.5f * hs.size[2]);
  const float hand_radius = glm::length(hh);
  const glm::mat4& th = m[static_cast<std::size_t>(thigh)];
  const glm::mat4& hm = m[static_cast<std::size_t>(hand)];
  // The hand's box in the thigh's space: its centre and half axes.
  const glm::mat3 to_thigh = glm::transpose(glm::mat3(th));
  const glm::vec3 c = to_thigh * (glm::vec3(hm * glm::vec4(hc, 1.0f)) - glm::vec3(th[3]));
  // Most frames: the hand's centre is further from the thigh's box than
  // its own half diagonal and the clearance.
  glm::vec3 n;
  const float centre_out = box_distance(ts, c, &n);
  if (centre_out > hand_radius - clear) return clear;
  const glm::mat3 axes = to_thigh * glm::mat3(hm);
  const glm::vec3 ax = axes[0] * hh.x, ay = axes[1] * hh.y, az = axes[2] * hh.z;
  // Many more: the plane through the thigh box's point nearest the hand's
  // centre, facing it, has the whole thigh box behind it (the box is
  // convex); no point of the hand's box is nearer that plane than the
  // centre's distance less the box's reach along its normal. When that is
  // the clearance and a margin far above float rounding, every sample
  // below is clear too: the same answer without its 45 distances (issue
  // 23: the animation of a full game within 1 s).
  const float reach = std::fabs(glm::dot(ax, n)) + std::fabs(glm::dot(ay, n)) + std::fabs(glm::dot(az, n));
  if (centre_out - reach > -clear + 1e-4f) return clear;
  float depth = -1.0f;  // the deepest sample point
  for (float sx : {-1.0f, 0.0f, 1.0f})
    for (float sy : {-1.0f, -0.5f, 0.0f, 0.5f, 1.0f})
      for (float sz : {-1.0f, 0.0f, 1.0f})
        depth = std::max(depth, -box_distance(ts, c + sx * ax + sy * ay + sz * az, nullptr));
  return depth;
}

}  // namespace

// A leg splayed sideways (a
// quick turn, a lateral lunge) or swinging forward past a hand swinging
// back would pass through it; instead the arm is lifted away from the body
// (shoulder abduction) a few degrees at a time until the hand's box is 6 cm
// clear of the thigh's, as a person moves the arm out of the way. The 6 cm
// keep them apart in the clients' blend between two frames as well: of the
// two full games' frames drawn at 60 Hz, 1 cm left 40 and 40 with a hand
// more than 2 cm inside, 3 cm 10 and 4, 5 cm 0 and 1, 6 cm none. With
// `last` (the frame before), the blend is checked too: a sprinter's raised
// knee, turned out 45 deg, came in as the arm swung back, from 5 cm clear
// on both frames to 3.2 cm inside a third of the way (game 2 seq 1920-1921,
// 60 Hz). Posed only where it can matter (kNearM, kBlendTurnDeg): posed
// wherever the hand was within 25 cm, it cost 8 % of the animation. A hand
// near its thigh in the frame before (`near`) is as near as one in this
// frame: a runner's thigh swung back past a hand that swung forward, the
// hand 11 cm out at the frame, 4 cm at the one before, and 2.5 cm inside
// half-way between as the clients draw it (game 1 seq 3640). 15 deg of turn
// let a hand pass 3.6 cm into a thigh turning 9.5 deg (game 2 seq 4747, at
// six of eight phases of the display): 5 deg, for 1.6 % more of the
// animation's instructions. Checked wherever the frame's hand was within
// 15 cm, the blend cost 16 %.
void keep_hands_off_thighs(const SkeletonDef& skel, std::span<float> a, std::span<const float> last, bool* near) {
  constexpr float kClearM = -0.06f;       // the hand's deepest point at least 6 cm outside the thigh
  constexpr float kBlendClearM = -0.01f;  // and in the clients' blend at least 1 cm
  constexpr float kNearM = -0.08f;        // a frame's hand this far out is not checked in the blend,
  constexpr float kBlendTurnDeg = 5.0f;   // nor one whose hip and shoulder turn less than this
  constexpr float kThirds[2] = {1.0f / 3.0f, 2.0f / 3.0f};
  std::array<glm::mat4, kHumanJointCount> m;
  if (!pose_hands(skel, a, m)) return;
  std::array<float, dof::kCount> between{};
  const bool blend = last.size() == a.size() && a.size() == between.size();
  for (int side = 0; side < 2; ++side) {
    const auto abduct = static_cast<std::size_t>((side == 0 ? dof::kRShoulder : dof::kLShoulder) + 1);
    const float outward = side == 0 ? -1.0f : 1.0f;  // the shoulder's x dof away from the body
    const auto& lim = skel.joints[static_cast<std::size_t>(side == 0 ? kRUpperArm : kLUpperArm)].limits[1];
    // Whether the blend is checked is decided once, from the frame as it
    // came: the arm turned out for it takes the frame's hand further out.
    bool in_blend = blend && side_turn(last, a, side) > kBlendTurnDeg;
    for (int it = 0; it < 6; ++it) {
      if (it > 0 && !pose_hands(skel, a, m)) return;
      // Metres the hand is to move out: at this frame, and (for a third
      // of the blend, moved by a third of this frame's turn) in between.
      // Read to kNearM where that is asked for (a hand further out reads
      // kNearM), else only to kClearM.
      const bool to_near = it == 0 && (in_blend || near != nullptr);
      float out = hand_in_thigh(skel, m, side, to_near ? kNearM : kClearM) - kClearM;
      if (it == 0) {
        const bool near_now = to_near && out > kNearM - kClearM;
        in_blend = in_blend && (near_now || (near != nullptr && near[side]));
        if (near != nullptr) near[side] = near_now;
      }
      if (in_blend) {
        for (float t : kThirds) {
          for (std::size_t d = 0; d < between.size(); ++d) between[d] = last[d] + (a[d] - last[d]) * t;
          std::array<glm::mat4, kHumanJointCount> mb;
          if (!pose_hands(skel, between, mb, kSideJoints[side])) return;
          out = std::max(out, (hand_in_thigh(skel, mb, side, kBlendClearM) - kBlendClearM) / t);
        }
      }
      if (out <= 0) break;
      // The hand is ~0.6 m from the shoulder: the angle that moves it
      // `out` further.
      const float step = std::max(0.5f, out / 0.6f * 57.2958f);
      const float before = a[abduct];
      a[abduct] = std::clamp(a[abduct] + outward * step, lim[0], lim[1]);
      if (a[abduct] == before) break;
    }
  }
}

float hand_depth_in_thigh(const SkeletonDef& skel, std::span<const float> a, std::span<const float> last, int side,
                          float far) {
  std::array<glm::mat4, kHumanJointCount> m;
  if (!pose_hands(skel, a, m, kSideJoints[side])) return -far;
  float depth = hand_in_thigh(skel, m, side, -far);
  if (last.size() == a.size() && a.size() == static_cast<std::size_t>(dof::kCount)) {
    std::array<float, dof::kCount> between{};
    for (const float t : {1.0f / 3.0f, 2.0f / 3.0f}) {
      for (std::size_t d = 0; d < between.size(); ++d) between[d] = last[d] + (a[d] - last[d]) * t;
      if (pose_hands(skel, between, m, kSideJoints[side])) depth = std::max(depth, hand_in_thigh(skel, m, side, -far));
    }
  }
  return depth;
}

// Legs keep out of each other: the thighs' and the shins' centre lines
// (capsules of the boxes' half widths, plus a margin for the stream's
// quantization) stay apart. A leg in the air is turned out at the hip
// (abduction) until they are, in up to three turns; with both in the air,
// the one further across. True when a leg is
// planted and the legs were too close (still, or before the last turn, which
// is not checked again): the caller then turns the planted knees out
// (LegPoseJob's knee_out_deg). Checking the last turn too gave the same
// figures at 20 Hz and 13 more thighs too close at 60 Hz on game 1 (790 ->
// 803): the extra turn leaves a margin for the clients' blend.
bool separate_legs(std::span<float> a, float pelvis_h, const bool planted[2]) {
  // Half a box width plus 3.5 cm: the margin covers the stream's
  // quantization (1 deg on each hip dof moves a knee 0.8 cm) and leaves room
  // for the clients' blend between frames. 1.5 cm left 19/15/15 and
  // 19/14/12 thighs / shins / feet too close at 20 Hz on the two full games
  // (60 Hz 803/124/180, 742/142/162); 3.5 cm leaves 5/8/8 and 1/5/10
  // (384/53/131, 359/39/131), for ankle pops at 60 Hz 126/124 -> 131/138;
  // 4.5 cm 3/7/9 and 1/3/11 for pops 146/150 (anim/README.md).
  constexpr float kThighGap = 0.07f + 0.035f, kShinGap = 0.05f + 0.035f, kFootGap = 0.05f + 0.035f;
  const glm::mat3 pelvis = joint_rotation(kYzx, &a[dof::kPelvis]);
  for (int it = 0; it < 3; ++it) {
    glm::vec3 hip[2], knee[2], ankle[2], heel[2], toe[2];
    for (int i = 0; i < 2; ++i) {
      const int h = i == 0 ? dof::kRHip : dof::kLHip;
      const glm::mat3 thigh = pelvis * joint_rotation(kZxy, &a[static_cast<std::size_t>(h)]);
      const glm::mat3 shin = thigh * joint_rotation(kZ, &a[static_cast<std::size_t>(h + 3)]);
      const glm::mat3 foot = shin * joint_rotation(kZx, &a[static_cast<std::size_t>(h + 4)]);
      hip[i] = glm::vec3(0, pelvis_h, 0) +
               pelvis * glm::vec3(0, -dims::kHipDrop, i == 0 ? dims::kHipHalfWidth : -dims::kHipHalfWidth);
      knee[i] = hip[i] + thigh * glm::vec3(0, -dims::kThigh, 0);
      ankle[i] = knee[i] + shin * glm::vec3(0, -dims::kShin, 0);
      heel[i] = ankle[i] + foot * glm::vec3(-dims::kFootBack, -0.5f * dims::kAnkleHeight, 0);
      toe[i] = ankle[i] + foot * glm::vec3(dims::kFootFront, -0.5f * dims::kAnkleHeight, 0);
    }
    const float thighs = segment_distance(hip[0], knee[0], hip[1], knee[1]);
    const float shins = segment_distance(knee[0], ankle[0], knee[1], ankle[1]);
    const float feet = segment_distance(heel[0], toe[0], heel[1], toe[1]);
    const float need = std::max({(kThighGap - thighs) / 0.3f, (kShinGap - shins) / 0.65f,
                                 (kFootGap - feet) / 0.85f});  // rad of abduction
    if (need <= 0) return false;
    int i = !planted[0] ? 0 : !planted[1] ? 1 : -1;
    if (i < 0) return true;
    if (!planted[0] && !planted[1]) {
      // Both feet up: the leg further across the body (its knee further
      // past its hip towards the other side) turns out. Turning the right
      // one always left game 1's largest case, a crossover step in a turn,
      // 3.1 cm inside: the right leg already abducted 14 deg, the left at
      // its adduction limit (anim/README.md).
      const glm::vec3 right = pelvis * glm::vec3(0, 0, 1);
      const float across_r = glm::dot(hip[0] - knee[0], right), across_l = glm::dot(knee[1] - hip[1], right);
      i = across_l > across_r ? 1 : 0;
    }
    const int h = i == 0 ? dof::kRHip : dof::kLHip;
    const float turn = std::min(need / kDeg + 1.0f, 25.0f);
    a[static_cast<std::size_t>(h + 1)] += i == 0 ? -turn : turn;  // right abducts towards -X, left towards +X
  }
  return planted[0] || planted[1];
}

int hip_turning_too_fast(std::span<const float> last, std::span<const float> a, float most_deg, int only) {
  for (int side = 0; side < 2; ++side) {
    if (only >= 0 && side != only) continue;
    const auto k = static_cast<std::size_t>(side == 0 ? dof::kRHip : dof::kLHip);
    bool fast = rotation_between(kZxy, &last[k], &a[k]) > most_deg;
    // Nor a third of the frame as the clients blend it (their angles
    // linearly at 60 Hz): a blend of Euler angles turns unevenly, and one
    // hip's last third turned 20.3 deg (60.9 deg per 50 ms) when the leg
    // further across turned out.
    float at[4][3];
    for (int n = 0; n < 4; ++n)
      for (std::size_t d = 0; d < 3; ++d)
        at[n][d] = last[k + d] + (a[k + d] - last[k + d]) * static_cast<float>(n) / 3.0f;
    for (int n = 0; n < 3 && !fast; ++n) fast = rotation_between(kZxy, at[n], at[n + 1]) > most_deg / 3.0f;
    if (fast) return side;
  }
  return -1;
}

void separate_legs_again(const SkeletonDef& skel, const BodyFrame& body, float pelvis_h, std::span<const float> last,
                         const AnkleTravel* travel, const bool planted[2], std::span<float> a) {
  std::array<float, dof::kCount> held;
  std::copy_n(a.begin(), dof::kCount, held.begin());
  auto hip_too_fast = [&] { return hip_turning_too_fast(last, a, kMaxLegStepDeg + kSeparateAgainDeg); };
  // One try with the legs in `fixed` held. A turn-out too fast in full is
  // taken as far as it keeps within the limits (bisection): refused whole,
  // it left a crossover step's shins 3.8 cm inside each other (game 2 seq
  // 11560, a kick's approach). Returns the hip that would turn too fast
  // even a little (the legs are then as they were), or -1.
  auto attempt = [&](const bool fixed[2]) {
    separate_legs(a, pelvis_h, fixed);
    clamp_to_limits(skel, a);
    const int side = hip_too_fast();
    if (side < 0) return -1;
    std::array<float, dof::kCount> full;
    std::copy_n(a.begin(), dof::kCount, full.begin());
    auto set = [&](float s) {
      for (std::size_t d = 0; d < full.size(); ++d) a[d] = held[d] + (full[d] - held[d]) * s;
    };
    float lo = 0, hi = 1;
    for (int it = 0; it < kTurnOutBisections; ++it) {
      const float mid = 0.5f * (lo + hi);
      set(mid);
      (hip_too_fast() < 0 ? lo : hi) = mid;
    }
    set(lo);
    return lo > 0 ? -1 : side;
  };
  const int too_fast = attempt(planted);
  // With both feet up, the leg that the speed limit holds may be the one
  // further across: then the other one turns out instead (game 1 seq 8679,
  // legs crossed in a flight phase, thighs 3.1 cm inside).
  if (too_fast >= 0 && !planted[0] && !planted[1]) {
    const bool hold[2] = {too_fast == 0, too_fast == 1};
    if (attempt(hold) >= 0) return;
  } else if (too_fast >= 0) {
    return;
  }
  if (std::equal(held.begin(), held.end(), a.begin())) return;
  if (travel != nullptr) limit_ankle_travel(skel, body, pelvis_h, *travel, held, a, kSeparationSlackM);
}

}  // namespace mc::anim
