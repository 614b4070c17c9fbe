// Legs drawn between two 20 Hz frames (issue 23): a study, not yet in the
// clients; matchcast-anim-quality --leg-blend measures it.
//
// The clients draw at the display's rate and blend two frames' joint angles
// linearly. Forward kinematics is not linear in the angles, so a foot that
// stands on the same spot in both frames leaves it in between: 1-2 cm at a
// third of a frame, which the eye reads as a sliding foot (the grounded foot
// moved at 0.84 m/s mean at 60 Hz against 0.40 at 20 Hz). This step runs
// after that blend: each leg whose foot stands on the grass in both frames
// is re-aimed so that its ankle lies on the straight line between its
// places in the two frames (a planted foot stays exactly where it is), and
// the sole turns from its first attitude to its second. A swinging foot
// keeps the blend's arc. anim/README.md has what it gives and costs. The hip and knee angles change by damped least squares from the
// blended angles, so the fix is zero at t = 0 and t = 1 and small between:
// the motion stays the frames' own.
//
// Works on any skeleton whose legs are a chain thigh -> shin -> foot off the
// root joint (found by name: "thigh"/"hip"/"upleg", "shin"/"knee"/"calf",
// "foot"/"ankle", one left and one right), the thigh with up to 3 dofs, the
// shin with 1 and the foot with up to 2. Without such legs it does nothing.
#pragma once

#include <array>

#include "proto/pose_frame.hpp"
#include "proto/skeleton.hpp"

namespace mc::anim {

class LegBlend {
 public:
  // `lift_and_land`: also the interval in which a foot leaves the grass
  // or lands on it (the foot stays until its sole clears the grass, or
  // arrives before it touches); otherwise only a foot on the grass in both.
  explicit LegBlend(const SkeletonDef& skeleton, bool lift_and_land = false);

  // True when both legs were found.
  bool ready() const { return legs_ == 2; }

  // `out` is the clients' blend of `a` and `b` at `t` (positions, heading
  // and angles; same player slots): re-aims its legs. A player whose slot
  // changes between the frames or whose root jumps `teleport_m` or more is
  // left as blended (a teleport is not animated).
  void apply(const PoseFrame& a, const PoseFrame& b, float t, PoseFrame& out, float teleport_m = 5.0f) const;

  // One player: `o` is the blend of `pa` and `pb` at `t`.
  void apply(const PlayerPose& pa, const PlayerPose& pb, float t, PlayerPose& o) const;

 private:
  struct Joint {
    int index = -1;
    int first_angle = 0;
    int dofs = 0;
  };
  struct Leg {
    Joint thigh, shin, foot;
  };

  const SkeletonDef& skeleton_;
  std::array<Leg, 2> leg_{};
  int legs_ = 0;
  bool lift_and_land_ = false;
};

}  // namespace mc::anim
