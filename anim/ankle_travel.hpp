// Ankles that do not pop (issue 23): between two frames an ankle moves at
// most kAnklePastPelvisM relative to the pelvis and kAnkleWorldStepM over
// the grass, whatever placed it (a swing re-planned in a turn, a kick's
// follow-through handed back to the footsteps, a foot planted by a take-over).
//
// The joint speed limit (player_animation.hpp) bounds each joint, but three
// hip dofs and a knee each turning within it still carry an ankle 0.8 m in
// one frame: a viewer sees the foot jump. This bounds the ankle itself: a
// target further off is pulled back along the way towards it, the leg is
// solved again, and the foot gets there on the frames after. Human skeleton
// only; no I/O.
#pragma once

#include <span>

#include <glm/vec3.hpp>

#include "anim/body_frame.hpp"
#include "anim/leg_pose_job.hpp"
#include "proto/skeleton.hpp"

namespace mc::anim {

// A sprinter's swinging foot passes the hip at up to about 10 m/s; the
// issue's pop is 0.6 m a frame relative to the pelvis or 1 m over the grass.
inline constexpr float kAnklePastPelvisM = 0.50f;
inline constexpr float kAnkleWorldStepM = 0.92f;

// Where the ankles and the pelvis were on the last frame (field x, y, height).
struct AnkleTravel {
  bool valid = false;
  glm::vec3 ankle[2]{};  // [0] right, [1] left
  glm::vec3 pelvis{};
};

// Field positions of both ankles for the pose `a` (deg) with the pelvis at
// height `pelvis_h` in `body`.
void ankle_positions(const SkeletonDef& skel, std::span<const float> a, float pelvis_h, const BodyFrame& body,
                     glm::vec3 out[2]);

// A spot an ankle must reach within `frames` more frames (a kick's
// contact, field x, y and height): on each frame before it, the ankle stays
// within that many frames' travel of it, the pelvis assumed to go on as it
// went on the last frame. Without it, a kicking foot that came late out of
// a run covered the whole way in the frame before its contact, up to 0.8 m
// past the pelvis (issue 23: 43 of the two full games' 55 ankle pops).
struct AnkleGoal {
  bool set = false;
  glm::vec3 at{};
  int frames = 1;
};

// Pulls back the targets of the legs in `legs` (already solved into
// legs.angles) whose ankles moved too far since `last`, or would be too far
// from their `goal` (may be null), and solves the legs again. `skip[i]`:
// leave that foot as it is (a kick's contact). `lift[i]`: a foot pulled back
// is on its way to a spot, so it is raised above the grass by half the way
// it has still to go (up to 8 cm). Returns a bit per foot pulled back (1
// right, 2 left).
int limit_ankle_travel(const SkeletonDef& skel, const BodyFrame& body, const AnkleTravel& last, const bool skip[2],
                       const bool lift[2], const AnkleGoal goal[2], LegPoseJob& legs);

// The same bounds, widened by `slack` (m), for a pose given as angles (a
// tackle's, a dive's, legs turned out of each other's way): each leg's
// change since `last_angles` (the pose it came from, within the bounds) is
// scaled down, by bisection, until its ankle keeps within them (or the leg
// is held as it was). Returns a bit per leg held back.
int limit_ankle_travel(const SkeletonDef& skel, const BodyFrame& body, float pelvis_h, const AnkleTravel& last,
                       std::span<const float> last_angles, std::span<float> a, float slack = 1e-3f);

// A frame's root as the clients blend it: field position (m), the pelvis
// joint's height (m) and heading (field deg).
struct DrawnRoot {
  float x = 0, y = 0, height = 0, heading = 0;
};

// The ankles' travel as the clients draw it. They blend the root and every
// angle linearly between two frames (proto/SPEC.md 4.7, step 1), so an
// ankle follows a curve, and part of the frame can carry it faster than
// the chord the bounds above hold: with every chord within them, 61 and 63
// foot-frames of the two full games popped at 60 Hz (issue 23). Each leg
// not in `skip` whose thirds of the drawn frame move its ankle faster than
// kDrawnPopM (over the grass) or kDrawnPopRelM (relative to the pelvis) per
// frame has its change since `last_angles` scaled down, by bisection, until
// they keep within. `last`, `last_angles`, `last_ankle`: the previous
// frame's root, angles and ankles (field x, y, height); `now`, `a`,
// `now_ankle`: this frame's (`a` changed in place). Returns a bit per leg
// held back (1 right, 2 left). Not checked, to keep it cheap: a leg whose
// path (each joint's turn times its lever) cannot pass the bounds, and a
// leg whose ankle ends within half a bound of where it was (a measured
// shortcut, not a proof; ankle_travel.cpp).
// kDrawnPopRelM leaves room under the 0.6 m for what the clients
// add: their swing of a leg about its hip (proto/SPEC.md 4.7 step 2, at
// most 1 deg, 1.5 cm at the ankle in a third of a frame: 0.045 m per
// frame). With 0.58 m the last two 60 Hz pops (game 1 seq 2378, game 2
// seq 8592) were such feet leaving the grass at 9 m/s, 0.61-0.62 m.
// 0.54, not 0.55 (session 34): the legs held back this little more pass
// through each other less in the blend (60 Hz legs too close over eight
// phases 3 and 3 -> 1 and 2), with no other figure moved past its rounding.
inline constexpr float kDrawnPopM = 0.97f;
inline constexpr float kDrawnPopRelM = 0.54f;
int limit_drawn_travel(const SkeletonDef& skel, const DrawnRoot& last, std::span<const float> last_angles,
                       const glm::vec3 last_ankle[2], const DrawnRoot& now, std::span<float> a,
                       const glm::vec3 now_ankle[2], const bool skip[2]);

}  // namespace mc::anim
