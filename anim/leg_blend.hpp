// Feet drawn between two 20 Hz frames (issue 23; proto/SPEC.md 4.7, step
// 2): what both clients draw after the linear blend, and what
// matchcast-anim-quality measures at their drawing rate.
//
// The clients draw at the display's rate and blend two frames' joint angles
// linearly. Forward kinematics is not linear in the angles, so a foot that
// stands on the grass in both frames leaves its line between them, and a
// foot that leaves or lands is dragged over the grass for part of the frame
// (its sole within 3 cm of it while it travels). Both read as a sliding
// foot. This step runs after the blend, leg by leg:
//   - a foot on the grass in both frames (its sole within kContactM, its
//     ankle moved less than kSameStanceM) keeps its ankle, across the grass,
//     on the straight line between its places in the two frames;
//   - a foot on the grass in one frame only is raised: its sole's height
//     follows 1 - (1 - t)^2 of the way (leaving) or t^2 (landing) instead
//     of t, so it rises at once and comes down steeply, as a runner's foot
//     does, instead of skimming the grass; and across the grass it starts
//     (leaving) or ends (landing) slowly.
// Each is done by swinging the whole leg about its hip joint (the thigh's
// rotation; the knee and the ankle keep their blended angles) by the
// rotation that takes the ankle towards its target, at most kMaxSwingDeg.
// The change is zero at t = 0 and t = 1 and small between, so the motion
// stays the frames' own.
// Then the legs are kept apart: both frames hold the legs' boxes apart
// (anim/limb_clearance.cpp), but a leg swinging past the other passes
// through it in the blend. A leg in the air turns at the hip, away from
// the other hip (for feet: from the other foot), until the centre lines of
// the two thighs, shins and feet are kApartM beyond half the wider box's
// width. The turn may grow only
// from nothing at either frame, at the rate the thigh's own turn over the
// frame leaves below kApartSpeedDeg, and at the rate its ankle's travel
// about the root leaves below kApartTravelM, up to kMaxApartDeg (a fast
// foot carried sideways reads as an ankle pop). An earlier version (damped least squares on hip
// and knee) also chased the blend's error in height, which step 3 (rest
// on the grass) deals with, and bent the knees for it: legs jerked at
// 60 Hz (86 deg per 50 ms). anim/README.md has what this one gives.
//
// Works on any skeleton whose legs are a chain thigh -> shin -> foot off the
// root joint (found by name: "thigh"/"hip"/"upleg", "shin"/"knee"/"calf",
// "foot"/"ankle", one left and one right), the thigh with 3 dofs about three
// different axes. Without such legs it does nothing.
#pragma once

#include <array>
#include <cmath>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "anim/segment_distance.hpp"
#include "proto/pose_frame.hpp"
#include "proto/skeleton.hpp"

namespace mc::anim {

class LegBlend {
 public:
  explicit LegBlend(const SkeletonDef& skeleton);

  // True when both legs were found.
  bool ready() const { return legs_ == 2; }

  // `out` is the clients' blend of `a` and `b` at `t` (positions, heading
  // and angles; same player slots): moves its legs. A player whose slot
  // changes between the frames or whose root jumps `teleport_m` or more is
  // left as blended (a teleport is not animated).
  void apply(const PoseFrame& a, const PoseFrame& b, float t, PoseFrame& out, float teleport_m = 5.0f) const;

  // One player: `o` is the blend of `pa` and `pb` at `t`. With `feet_way`:
  // the way the step's first round parted the feet (the first foot's
  // middle from the nearest point of the other foot's centre line, body
  // space), or zero when it did not (anim::keep_legs_apart_drawn reads
  // where that way turns fast: the step may let the feet through each
  // other there).
  void apply(const PlayerPose& pa, const PlayerPose& pb, float t, PlayerPose& o, glm::vec3* feet_way = nullptr) const;

  // What the step takes from the two frames alone, the same at every `t`:
  // where each pose puts each foot, each ankle's travel about the root and
  // each thigh's turn over the frame. A caller that draws one pair of
  // frames at many points (anim::keep_legs_apart_drawn) takes it once.
  struct FootPlace {
    glm::vec3 ankle{0.0f};  // field space (x, height, y)
    float sole = 0;         // the foot box's lowest corner above the grass (m)
  };
  struct Frames {
    FootPlace place[2][2];  // [leg][frame a, frame b]
    float travel[2] = {0, 0};
    float thigh_turn_deg[2] = {0, 0};
  };
  Frames frames(const PlayerPose& pa, const PlayerPose& pb) const;
  // apply() given frames(pa, pb): the same pose, to the last bit.
  void apply(const Frames& f, float t, PlayerPose& o, glm::vec3* feet_way = nullptr) const;

  // How far apart the legs' boxes are in pose `o`: the least distance
  // between the centre lines of the two thighs, the two shins and the two
  // feet, less half the wider box's width (m; anim-quality's clearance,
  // < 0 too close). INFINITY without legs.
  float clearance(const PlayerPose& o) const;

  // clearance() of the pose whose angles are those of `a` and `b` blended
  // at `t` (a + (b - a) t, as the clients blend them), roughly: with float
  // sines and cosines (rough_sincos.hpp) instead of the remembered double
  // ones, whose table a blend's new angles only crowd, and the segments'
  // ends carried by elementary rotations instead of matrices. Within a
  // tenth of kRoughClearanceM of clearance() of that pose over the joints'
  // whole range (anim_leg_blend_test). NaN where it cannot tell (a joint of
  // more than three dofs, an angle out of range or NaN). For a gate
  // (keep_legs_apart_drawn): a rough figure more than kRoughClearanceM from
  // a bound is on the same side of it as the exact one.
  float rough_clearance(const float* a, const float* b, float t) const;
  static constexpr float kRoughClearanceM = 0.001f;

  // Where pose `p` puts leg `i`'s ankle (0 and 1 in the order found; the
  // human skeleton's right, then left): field space written as (x, height,
  // y), as anim-quality measures an ankle's travel. With `sole`, also the
  // height of its foot box's lowest corner (m).
  glm::vec3 ankle(const PlayerPose& p, int i, float* sole = nullptr) const;

  // A foot is on the grass when its box's lowest corner is this low (m; the
  // height at which a viewer sees it touch, and anim-quality's contact).
  static constexpr float kContactM = 0.03f;
  // Both frames on the grass and the ankle this close: one stance (m).
  static constexpr float kSameStanceM = 0.3f;
  // The largest swing of a leg about its hip (deg).
  static constexpr float kMaxSwingDeg = 1.0f;
  // A foot leaving or landing moves across the grass t -/+ kAcrossEase t
  // (1 - t) of its way, the way taken kAcrossWayM at most. On the two full
  // games at 60 Hz the 4-5 m/s bands went 0.51 / 0.51 -> 0.47 / 0.47 m/s;
  // with 0.75 and 0.2 m the same; with 1 and no bound on the way the 6-8
  // m/s bands rose by 0.08 and ankles popped.
  static constexpr float kAcrossEase = 0.5f;
  static constexpr float kAcrossWayM = 0.15f;
  // The legs' boxes keep this far apart beyond half the wider box's width,
  // centre line to centre line (m; anim-quality's clearance).
  static constexpr float kApartM = 0.01f;
  // The largest turn of a leg out of the other's way (deg).
  static constexpr float kMaxApartDeg = 8.0f;
  // A leg turns out only while its thigh turns slower than this (deg per
  // frame; anim-quality's limit is 60), and the turn grows at most at the
  // difference per frame from either frame.
  static constexpr float kApartSpeedDeg = 54.0f;
  // The ankle's travel about the root over the frame and the turn's
  // sideways move of it together (m; anim-quality counts 0.6 as an ankle
  // pop), the turn's move taken at this distance from the hip (m).
  static constexpr float kApartTravelM = 0.47f;
  static constexpr float kApartLeverM = 0.85f;
  // How many times the legs are posed and turned apart (each round takes
  // up what the one before left). With every leg turned out from the
  // other hip, 2 rounds left 65 and 52 player-frames of feet too close on
  // the two full games at 60 Hz, 4 left 46 and 39; with feet parted along
  // their line, 4 and 6 rounds both leave 30-31.
  static constexpr int kApartRounds = 4;

 private:
  struct Joint {
    int index = -1;
    int first_angle = 0;
    int dofs = 0;
    // The segment's box: its centre line (the longest axis, end to end, in
    // the joint's space) and half its larger other side; absent for a
    // segment that is not a box.
    bool box = false;
    glm::vec3 line_from{0.0f}, line_to{0.0f};
    float half_width = 0;
  };
  struct Leg {
    Joint thigh, shin, foot;
  };

  // The pair of boxes (thighs, shins or feet) least clear of each other in
  // the posed legs: its clearance (as clearance() above), whether it is
  // the feet, and its centre lines' nearest points.
  struct Nearest {
    float clearance = INFINITY;
    bool feet = false;
    ClosestPoints closest;
  };
  Nearest nearest(const glm::mat4 thigh[2], const glm::mat4 shin[2], const glm::mat4 foot[2]) const;
  // Turns a leg's thigh by `rotation` (body space, about the hip joint);
  // `pelvis` and `thigh` are the root's and the thigh's model transforms.
  void turn_thigh(const Leg& leg, const glm::mat4& pelvis, const glm::mat4& thigh, const glm::mat3& rotation,
                  float* angles) const;
  // The second part of the step: the legs' boxes kept apart. `free`: how
  // freely each leg may turn whatever its drawn sole (1 off the grass in
  // both frames, t leaving it, 1 - t landing, 0 on it); `room`: how far each leg may
  // still turn (rad), and `along` how far in a turn that may carry its
  // ankle along its travel; both used up as it turns.
  // `fixed`: the transforms the step never turns, posed once by apply():
  // the root's model transform and each leg's shin's and foot's local ones.
  struct Fixed {
    glm::mat4 pelvis{1.0f};
    glm::mat4 shin[2]{glm::mat4(1.0f), glm::mat4(1.0f)};
    glm::mat4 foot[2]{glm::mat4(1.0f), glm::mat4(1.0f)};
  };
  void keep_apart(const float free[2], float room[2], float along[2], const Fixed& fixed, PlayerPose& o,
                  glm::vec3* feet_way) const;

  const SkeletonDef& skeleton_;
  std::array<Leg, 2> leg_{};
  int legs_ = 0;
};

}  // namespace mc::anim
