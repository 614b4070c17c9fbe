#include "anim/ankle_travel.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "anim/ground_contact.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/local_to_model_job.hpp"
#include "anim/sincos_deg.hpp"

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

// Scales the change of the leg whose dofs (hip 3, knee, ankle 2) start at
// `first`, since `last_angles`, down to the largest share (found by
// bisection, within 1/64; 0 if none) for which `ok()` holds of `a`.
template <typename Ok>
void scale_leg_back(std::span<const float> last_angles, std::span<float> a, int first, Ok ok) {
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
    (ok() ? lo : hi) = mid;
  }
  set(lo);
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
    scale_leg_back(last_angles, a, i == 0 ? dof::kRHip : dof::kLHip, [&] {
      glm::vec3 p[2];
      ankle_positions(skel, a, pelvis_h, body, p);
      return within(last, i, pelvis, p[i], slack);
    });
    held |= 1 << i;
  }
  return held;
}

namespace {

// The pelvis joint -> a hip joint (m, at most).
constexpr float kPelvisToHipM = 0.12f;

// An angle blended from `from` to `to` (deg), at 1/3 ([0]) and 2/3 ([1])
// of the way: its sines and cosines, from the end's (posed last, so
// remembered) and a third of the turn's, by the angle-sum formulas. Half
// the trigonometry of posing the two blends afresh.
struct Thirds {
  float s[2], c[2];
  Thirds(float from, float to) {
    float s1, c1, sd, cd;
    sincos_deg(to, s1, c1);
    // A third of a frame's turn is small (a joint turns at most 60 deg a
    // frame): Taylor series to the 7th power, within 1e-6 below 0.6 rad.
    // (Not remembered: it would only push out angles that are posed again.)
    const float d = (from - to) * (kDeg / 3.0f);
    if (std::fabs(d) < 0.6f) {
      const float d2 = d * d;
      sd = d * (1.0f - d2 * (1.0f / 6.0f) * (1.0f - d2 * (1.0f / 20.0f) * (1.0f - d2 * (1.0f / 42.0f))));
      cd = 1.0f - d2 * 0.5f * (1.0f - d2 * (1.0f / 12.0f) * (1.0f - d2 * (1.0f / 30.0f)));
    } else {
      pm::sincos(d, sd, cd);
    }
    const float s2d = 2.0f * sd * cd, c2d = cd * cd - sd * sd;
    s[1] = s1 * cd + c1 * sd;
    c[1] = c1 * cd - s1 * sd;
    s[0] = s1 * c2d + c1 * s2d;
    c[0] = c1 * c2d - s1 * s2d;
  }
};

// The root as the clients draw it 1/3 and 2/3 of the way through a frame:
// its place on the field and its rotation (the pelvis joint's dofs).
struct DrawnBody {
  BodyFrame frame;
  glm::vec3 pelvis{0.0f};  // the pelvis joint in body space
  glm::mat3 rotation{1.0f};
};

// Leg `i`'s ankle (field x, y, height) for the drawn root `r` and the
// leg's hip and knee rotations: the chain pelvis -> thigh -> shin -> foot
// joint alone.
glm::vec3 leg_ankle(const SkeletonDef& skel, const DrawnBody& r, const glm::mat3& hip, const glm::mat3& knee, int i) {
  const auto& j = skel.joints;
  const std::size_t thigh = i == 0 ? kRThigh : kLThigh;
  auto offset = [&](std::size_t k) { return glm::vec3(j[k].offset_ls[0], j[k].offset_ls[1], j[k].offset_ls[2]); };
  const glm::vec3 p = r.pelvis + r.rotation * (offset(thigh) + hip * (offset(thigh + 1) + knee * offset(thigh + 2)));
  glm::vec3 out;
  r.frame.to_field(p.x, p.z, out.x, out.y);
  out.z = p.y;
  return out;
}

}  // namespace

int limit_drawn_travel(const SkeletonDef& skel, const DrawnRoot& last, std::span<const float> last_angles,
                       const glm::vec3 last_ankle[2], const DrawnRoot& now, std::span<float> a,
                       const glm::vec3 now_ankle[2], const bool skip[2]) {
  if (last_angles.size() < static_cast<std::size_t>(dof::kCount) || a.size() < static_cast<std::size_t>(dof::kCount) ||
      skel.joints.size() < static_cast<std::size_t>(kHumanJointCount))
    return 0;
  if (skip[0] && skip[1]) return 0;
  // Most legs need no more: an angle blended linearly turns at a steady
  // rate, a rotation of three such angles at most at the sum of theirs, so
  // the ankle's path about the pelvis over the frame is at most each
  // joint's turn (and the heading's) times its lever, summed. A third of
  // the frame takes a third of it.
  auto turn = [&](int first, int n) {
    float sum = 0;
    for (int d = first; d < first + n; ++d)
      sum += std::fabs(a[static_cast<std::size_t>(d)] - last_angles[static_cast<std::size_t>(d)]);
    return sum * kDeg;
  };
  // Headings are within [-180, 180): the short way round without fmod
  // (which cost a sixth of this check).
  float heading_turn = now.heading - last.heading;
  if (heading_turn >= 180.0f) heading_turn -= 360.0f;
  else if (heading_turn < -180.0f) heading_turn += 360.0f;
  const glm::vec3 root_step(now.x - last.x, now.y - last.y, now.height - last.height);
  // The drawn root at 1/3 and 2/3 of the frame, made when first needed.
  std::optional<std::array<DrawnBody, 2>> bodies;
  auto drawn_body = [&](int n) -> const DrawnBody& {
    if (!bodies) {
      auto& body = bodies.emplace();
      const auto& root = skel.joints[kPelvis];
      const Thirds heading(now.heading - heading_turn, now.heading);
      const Thirds r[3] = {{last_angles[dof::kPelvis], a[dof::kPelvis]},
                           {last_angles[dof::kPelvis + 1], a[dof::kPelvis + 1]},
                           {last_angles[dof::kPelvis + 2], a[dof::kPelvis + 2]}};
      for (int k = 0; k < 2; ++k) {
        const float t = static_cast<float>(k + 1) / 3.0f;
        BodyFrame& f = body[k].frame;
        f.x = last.x + root_step.x * t;
        f.y = last.y + root_step.y * t;
        f.heading = last.heading + heading_turn * t;
        f.s = heading.s[k];
        f.c = heading.c[k];
        body[k].pelvis = glm::vec3(root.offset_ls[0], root.offset_ls[1] + last.height + root_step.z * t, root.offset_ls[2]);
        const float sn[3] = {r[0].s[k], r[1].s[k], r[2].s[k]}, cs[3] = {r[0].c[k], r[1].c[k], r[2].c[k]};
        body[k].rotation = joint_rotation(root.dofs, sn, cs);
      }
    }
    return (*bodies)[static_cast<std::size_t>(n)];
  };
  // Leg `i`'s ankle drawn 1/3 and 2/3 of the way, its angles as `a` holds them.
  auto drawn = [&](int i, glm::vec3 out[2]) {
    const std::size_t first = i == 0 ? dof::kRHip : dof::kLHip;
    const std::size_t thigh = i == 0 ? kRThigh : kLThigh;
    const Thirds h[4] = {{last_angles[first], a[first]},
                         {last_angles[first + 1], a[first + 1]},
                         {last_angles[first + 2], a[first + 2]},
                         {last_angles[first + 3], a[first + 3]}};
    for (int k = 0; k < 2; ++k) {
      const float sn[3] = {h[0].s[k], h[1].s[k], h[2].s[k]}, cs[3] = {h[0].c[k], h[1].c[k], h[2].c[k]};
      const glm::mat3 hip = joint_rotation(skel.joints[thigh].dofs, sn, cs);
      const glm::mat3 knee = joint_rotation(skel.joints[thigh + 1].dofs, &h[3].s[k], &h[3].c[k]);
      out[k] = leg_ankle(skel, drawn_body(k), hip, knee, i);
    }
  };
  // Whether a third of the drawn frame moves leg `i`'s ankle too fast over
  // the grass or about the pelvis; `end`: its ankle at the frame.
  auto too_fast = [&](int i, const glm::vec3& end) {
    glm::vec3 mid[2];
    drawn(i, mid);
    const glm::vec3 at[4] = {last_ankle[i], mid[0], mid[1], end};
    for (int n = 0; n < 3; ++n) {
      const glm::vec3 move = at[n + 1] - at[n];
      if (3.0f * glm::length(move) > kDrawnPopM || 3.0f * glm::length(move - root_step / 3.0f) > kDrawnPopRelM)
        return true;
    }
    return false;
  };
  int held = 0;
  for (int i = 0; i < 2; ++i) {
    if (skip[i]) continue;
    const int first = i == 0 ? dof::kRHip : dof::kLHip;
    // A leg whose ankle ends less than half a bound from where it was
    // (over the grass or about the pelvis) is left unchecked: its path
    // would have to curve back on itself for a third to pass a third of
    // the bound. Not a proof, a measured shortcut: no leg held on the two
    // full games ended below 0.79 of a bound, and three quarters of the
    // legs the path bound leaves to check end below half of one (their
    // forward kinematics cost 2 % of the animation's time).
    const glm::vec3 chord = now_ankle[i] - last_ankle[i], chord_rel = chord - root_step;
    constexpr float kHalfM = 0.5f * kDrawnPopM, kHalfRelM = 0.5f * kDrawnPopRelM;
    if (glm::dot(chord, chord) < kHalfM * kHalfM && glm::dot(chord_rel, chord_rel) < kHalfRelM * kHalfRelM) continue;
    const float root_turn = turn(dof::kPelvis, 3) + std::fabs(heading_turn) * kDeg;
    const float root_move = glm::length(root_step);
    auto slow = [&](float path) { return path <= kDrawnPopRelM && path + root_move <= kDrawnPopM; };
    const float hip_turn = turn(first, 2), twist_turn = turn(first + 2, 1), knee_turn = turn(first + 3, 1);
    // With the longest levers: the whole leg from the hip, the shin for the
    // hip's twist (about the thigh) and for the knee.
    constexpr float kLegM = dims::kThigh + dims::kShin;
    if (slow(root_turn * (kPelvisToHipM + kLegM) + hip_turn * kLegM + (twist_turn + knee_turn) * dims::kShin)) continue;
    // Closer: the hip -> ankle lever is longest where the knee is
    // straightest, at one end of the blend (or straight, if it passes
    // through): the law of cosines, with cos x <= 1 - x^2/2 + x^4/24 (0.0417). The
    // twist moves the ankle only as far as the bent knee holds it off the
    // thigh's line: the shin times sin(bend) <= bend.
    const float k0 = last_angles[static_cast<std::size_t>(first + 3)] * kDeg;
    const float k1 = a[static_cast<std::size_t>(first + 3)] * kDeg;
    const float x = k0 * k1 <= 0.0f ? 0.0f : std::min(std::fabs(k0), std::fabs(k1));
    const float cos_most = std::min(1.0f, 1.0f - 0.5f * x * x + x * x * x * x * 0.0417f);
    const float hip_lever = std::sqrt(std::max(0.0f, dims::kThigh * dims::kThigh + dims::kShin * dims::kShin +
                                                         2.0f * dims::kThigh * dims::kShin * cos_most));
    const float twist_lever = dims::kShin * std::min(1.0f, std::max(std::fabs(k0), std::fabs(k1)));
    const float path = root_turn * (kPelvisToHipM + hip_lever) + hip_turn * hip_lever + twist_turn * twist_lever +
                       knee_turn * dims::kShin;
    if (slow(path) || !too_fast(i, now_ankle[i])) continue;
    // Judged with the frame's own ankle for the leg as it is scaled.
    scale_leg_back(last_angles, a, first, [&] {
      glm::vec3 p[2];
      ankle_positions(skel, a, now.height, BodyFrame(now.x, now.y, now.heading), p);
      return !too_fast(i, p[i]);
    });
    held |= 1 << i;
  }
  return held;
}

}  // namespace mc::anim
