#include "anim/ankle_travel.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "anim/ground_contact.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/local_to_model_job.hpp"

namespace mc::anim {

void ankle_positions(const SkeletonDef& skel, std::span<const float> a, float pelvis_h, const BodyFrame& body,
                     glm::vec3 out[2]) {
  std::array<glm::mat4, kHumanJointCount> m{};
  LocalToModelJob fk{&skel, a, glm::vec3(0, pelvis_h, 0), m};
  fk.joint_mask = kLegJoints;
  if (!fk.Run()) return;
  const int joint[2] = {kRFoot, kLFoot};
  for (int i = 0; i < 2; ++i) {
    const glm::vec3 p(m[static_cast<std::size_t>(joint[i])][3]);
    body.to_field(p.x, p.z, out[i].x, out[i].y);
    out[i].z = p.y;
  }
}

namespace {

constexpr int kAnkleTravelPasses = 3;
// Targets this far inside both bounds need no check (m): a leg that cannot
// reach its target leaves the ankle short of it by less.
constexpr float kSureM = 0.15f;
constexpr float kSideBySideM = 0.32f;  // m along the body within which two ankles are side by side
constexpr float kAnkleGapM = 0.16f;    // m sideways they keep apart then
constexpr float kShortFootLiftM = 0.08f;  // highest lift of a foot held short of its spot (m)
constexpr int kBisections = 6;  // a leg's change found to within 1/64
constexpr int kGoalProjections = 4;  // alternating projections between a frame's travel and a goal's reach
// A foot on its way to a goal may go this much further from its last place
// in a frame (m): still 5 cm inside the pop. Without it, 4 of the two
// full games' kicks came late out of a run and stopped 4-12 cm short of the
// ball.
constexpr float kGoalSlackM = 0.05f;

// `v` no longer than `len`.
glm::vec3 capped(const glm::vec3& v, float len) {
  const float n = glm::length(v);
  return n > len ? v * (len / n) : v;
}

// True when ankle `now` keeps within both bounds of `last`'s ankle `i`,
// each widened by `slack` (m; negative: that far inside).
bool within(const AnkleTravel& last, int i, const glm::vec3& pelvis, const glm::vec3& now, float slack) {
  const glm::vec3 rel = (now - pelvis) - (last.ankle[i] - last.pelvis);
  return glm::length(rel) <= kAnklePastPelvisM + slack && glm::length(now - last.ankle[i]) <= kAnkleWorldStepM + slack;
}

// True when `p` lies within `goal`'s travel (less `margin`, m), the pelvis
// going on by `pelvis_step` a frame until then.
bool reaches(const AnkleGoal& goal, const glm::vec3& pelvis_step, const glm::vec3& p, float margin) {
  const auto n = static_cast<float>(goal.frames);
  return glm::length(goal.at - n * pelvis_step - p) <= n * kAnklePastPelvisM - margin &&
         glm::length(goal.at - p) <= n * kAnkleWorldStepM - margin;
}

// `p` brought within `goal`'s travel: nearest point of the two balls'
// bounds, one after the other.
glm::vec3 towards_goal(const AnkleGoal& goal, const glm::vec3& pelvis_step, const glm::vec3& p) {
  const auto n = static_cast<float>(goal.frames);
  const glm::vec3 rel_centre = goal.at - n * pelvis_step;
  const glm::vec3 q = rel_centre + capped(p - rel_centre, n * kAnklePastPelvisM);
  return goal.at + capped(q - goal.at, n * kAnkleWorldStepM);
}

}  // namespace

int limit_ankle_travel(const SkeletonDef& skel, const BodyFrame& body, const AnkleTravel& last, const bool skip[2],
                       const bool lift[2], const AnkleGoal goal[2], LegPoseJob& legs) {
  if (!last.valid) return 0;
  const glm::vec3 pelvis(body.x, body.y, legs.pelvis_height);
  const glm::vec3 pelvis_step = pelvis - last.pelvis;
  auto has_goal = [&](int i) { return goal != nullptr && goal[i].set; };
  // Most frames the targets themselves are well inside both bounds: the
  // solved ankles (on their targets, or a little short of them towards the
  // hip) are then inside too, and no forward kinematics is needed.
  bool inside = true;
  for (int i = 0; i < 2 && inside; ++i) {
    const FootTarget& f = legs.feet[i];
    glm::vec3 target;
    body.to_field(f.ankle_ms[0], f.ankle_ms[2], target.x, target.y);
    target.z = f.ankle_ms[1];
    inside = skip[i] || (within(last, i, pelvis, target, -kSureM) &&
                         (!has_goal(i) || reaches(goal[i], pelvis_step, target, kSureM)));
  }
  if (inside) return 0;
  // Where the legs as solved put the ankles, and where each may go instead.
  glm::vec3 solved[2], want[2];
  ankle_positions(skel, legs.angles, legs.pelvis_height, body, solved);
  // `p` brought within a frame's travel of ankle `i`: relative to the pelvis
  // first, then over the grass (the second only shortens the first's step).
  auto from_last = [&](int i, const glm::vec3& p) {
    const float sl = has_goal(i) ? kGoalSlackM : 0.0f;
    const glm::vec3 rel_last = last.ankle[i] - last.pelvis;
    const glm::vec3 q = pelvis + rel_last + capped(p - pelvis - rel_last, kAnklePastPelvisM + sl);
    return last.ankle[i] + capped(q - last.ankle[i], kAnkleWorldStepM + sl);
  };
  // Within a frame of the last ankle and, with a goal, within reach of it:
  // alternate projections onto the two (convex) regions; the last frame's
  // bound is applied last, so it always holds.
  auto bounded = [&](int i, const glm::vec3& p) {
    if (!has_goal(i)) return from_last(i, p);
    glm::vec3 q = p;
    for (int it = 0; it < kGoalProjections; ++it) q = from_last(i, towards_goal(goal[i], pelvis_step, q));
    return q;
  };
  int pulled = 0;
  for (int i = 0; i < 2; ++i) {
    if (skip[i]) continue;
    want[i] = bounded(i, solved[i]);
    if (glm::length(want[i] - solved[i]) < 0.01f) continue;
    if (lift[i]) {
      const float rest = glm::length(glm::vec2(solved[i] - want[i]));
      want[i].z = std::max(want[i].z, solved[i].z + std::min(kShortFootLiftM, 0.5f * rest));
    }
    pulled |= 1 << i;
  }
  // Held short on the straight way to its target, a foot can end up on the
  // other's side: it keeps to its own, a sole's width clear, as a swing does.
  for (int i = 0; i < 2; ++i) {
    if ((pulled & (1 << i)) == 0) continue;
    const glm::vec3& other = (pulled & (1 << (1 - i))) != 0 ? want[1 - i] : solved[1 - i];
    const float side = i == 0 ? 1.0f : -1.0f;  // right is +Z in body space
    float bx, bz, ox, oz;
    body.to_body(want[i].x, want[i].y, bx, bz);
    body.to_body(other.x, other.y, ox, oz);
    if (std::fabs(bx - ox) < kSideBySideM && side * (bz - oz) < kAnkleGapM) {
      body.to_field(bx, oz + side * kAnkleGapM, want[i].x, want[i].y);
      want[i] = bounded(i, want[i]);  // and still within a frame's travel
    }
  }
  // The IK leaves an ankle short of a target out of reach, so the target
  // is moved by what the ankle still has to give up, up to three times.
  for (int it = 0; it < kAnkleTravelPasses && pulled != 0; ++it) {
    glm::vec3 now[2];
    ankle_positions(skel, legs.angles, legs.pelvis_height, body, now);
    bool moved = false;
    for (int i = 0; i < 2; ++i) {
      if ((pulled & (1 << i)) == 0 || glm::length(want[i] - now[i]) < 0.01f) continue;
      const glm::vec3 shift = want[i] - now[i];
      float sx, sz;
      body.to_body(body.x + shift.x, body.y + shift.y, sx, sz);
      FootTarget& f = legs.feet[i];
      f.ankle_ms[0] += sx;
      f.ankle_ms[1] += shift.z;
      f.ankle_ms[2] += sz;
      moved = true;
    }
    if (!moved) break;
    legs.Run();
  }
  return pulled;
}

int limit_ankle_travel(const SkeletonDef& skel, const BodyFrame& body, float pelvis_h, const AnkleTravel& last,
                       std::span<const float> last_angles, std::span<float> a, float slack) {
  if (!last.valid || last_angles.size() < static_cast<std::size_t>(dof::kCount) ||
      a.size() < static_cast<std::size_t>(dof::kCount))
    return 0;
  const glm::vec3 pelvis(body.x, body.y, pelvis_h);
  glm::vec3 now[2];
  ankle_positions(skel, a, pelvis_h, body, now);
  int held = 0;
  for (int i = 0; i < 2; ++i) {
    if (within(last, i, pelvis, now[i], slack)) continue;
    // The leg's dofs (hip 3, knee, ankle 2) from last frame's towards this one's.
    const int first = i == 0 ? dof::kRHip : dof::kLHip;
    std::array<float, 6> to{};
    for (int d = 0; d < 6; ++d) to[static_cast<std::size_t>(d)] = a[static_cast<std::size_t>(first + d)];
    auto set = [&](float s) {
      for (int d = 0; d < 6; ++d) {
        const auto k = static_cast<std::size_t>(first + d);
        a[k] = last_angles[k] + (to[static_cast<std::size_t>(d)] - last_angles[k]) * s;
      }
    };
    float lo = 0, hi = 1;
    for (int it = 0; it < kBisections; ++it) {
      const float mid = 0.5f * (lo + hi);
      set(mid);
      glm::vec3 p[2];
      ankle_positions(skel, a, pelvis_h, body, p);
      (within(last, i, pelvis, p[i], slack) ? lo : hi) = mid;
    }
    set(lo);
    held |= 1 << i;
  }
  return held;
}

}  // namespace mc::anim
