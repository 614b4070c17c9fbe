#include "anim/kick_reach.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "anim/body_frame.hpp"
#include "anim/ground_contact.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/joint_limits.hpp"
#include "anim/limb_clearance.hpp"
#include "anim/local_to_model_job.hpp"
#include "anim/player_animation.hpp"
#include "anim/portable_math.hpp"

namespace mc::anim {
namespace {

// Rotation by `angle` (rad) about unit axis `n` (Rodrigues).
glm::mat3 axis_turn(const glm::vec3& n, float angle) {
  float s, c;
  pm::sincos(angle, s, c);
  const float t = 1.0f - c;
  return glm::mat3(t * n.x * n.x + c, t * n.x * n.y + s * n.z, t * n.x * n.z - s * n.y,
                   t * n.x * n.y - s * n.z, t * n.y * n.y + c, t * n.y * n.z + s * n.x,
                   t * n.x * n.z + s * n.y, t * n.y * n.z - s * n.x, t * n.z * n.z + c);
}

}  // namespace

void touch_ball(const SkeletonDef& skel, const BodyFrame& body, float& pelvis_h, const ActionSample& act, int k,
                LegPoseJob& legs, std::span<float> a) {
  const int foot = k == 0 ? kRFoot : kLFoot;
  const Segment& seg = skel.joints[static_cast<std::size_t>(foot)].segment;
  glm::vec3 ball(0.0f, act.ball_h, 0.0f);
  body.to_body(act.ball_x, act.ball_y, ball.x, ball.z);
  bool can_sink = true;
  std::array<glm::mat4, kHumanJointCount> m;
  // The other leg keeps its pose unless the pelvis sinks.
  const int other_dof = k == 0 ? dof::kLHip : dof::kRHip;
  float other[6];
  for (int d = 0; d < 6; ++d) other[d] = a[static_cast<std::size_t>(other_dof + d)];
  const float start_pelvis = legs.pelvis_height;
  auto solve = [&] {
    legs.Run();
    if (legs.pelvis_height == start_pelvis)
      for (int d = 0; d < 6; ++d) a[static_cast<std::size_t>(other_dof + d)] = other[d];
    clamp_to_limits(skel, a);
  };
  for (int it = 0; it < 6; ++it) {
    LocalToModelJob fk{&skel, std::span<const float>(a.data(), a.size()), glm::vec3(0, legs.pelvis_height, 0), m};
    fk.joint_mask = kLegJoints;
    if (!fk.Run()) return;
    const glm::mat4& fm = m[static_cast<std::size_t>(foot)];
    const glm::mat3 rot(fm);
    const glm::vec3 local = glm::transpose(rot) * (ball - glm::vec3(fm[3]));
    glm::vec3 n_local;
    const float gap = box_distance(seg, local, &n_local) - act.ball_r;
    if (std::fabs(gap - kContactGapM) < 0.001f) break;
    const glm::vec3 move = rot * n_local * (gap - kContactGapM);  // towards the ball when too far
    for (int c = 0; c < 3; ++c) legs.feet[k].ankle_ms[c] += move[c];
    legs.feet[k].ankle_ms[1] = std::max(legs.feet[k].ankle_ms[1], min_ankle_height(legs.feet[k].pitch_deg));
    // Out of the leg's reach: the pelvis sinks (a lunge), a little at a
    // time, as long as no foot goes into the grass.
    const float before = legs.pelvis_height;
    if (!legs.reached[k] && it > 0 && can_sink) legs.pelvis_height = std::max(legs.pelvis_height - 0.04f, 0.6f);
    solve();
    if (legs.pelvis_height != before) {
      LocalToModelJob fk2{&skel, std::span<const float>(a.data(), a.size()), glm::vec3(0, legs.pelvis_height, 0), m};
      fk2.joint_mask = kLegJoints;
      if (fk2.Run() && lowest_point_ms(skel, m, kFeetJoints) < -0.005f) {
        legs.pelvis_height = before;
        can_sink = false;
        solve();
      }
    }
  }
  pelvis_h = legs.pelvis_height;
  // Whatever the leg could not reach, the foot stays out of the grass.
  LocalToModelJob fk{&skel, std::span<const float>(a.data(), a.size()), glm::vec3(0, pelvis_h, 0), m};
  fk.joint_mask = kLegJoints;
  for (int it = 0; it < 3 && fk.Run(); ++it) {
    const float low = level_foot(skel, m, a, foot, k == 0 ? dof::kRAnkle : dof::kLAnkle);
    if (low >= -0.002f) break;
    legs.feet[k].ankle_ms[1] -= low;
    solve();
  }
}

float reach_ball_with_hip(const SkeletonDef& skel, std::span<const float> last, float pelvis_h, const glm::vec3& ball_ms,
                          float ball_r, int k, float gap_m, float cap_deg, std::span<float> a) {
  const int thigh = k == 0 ? kRThigh : kLThigh, foot = k == 0 ? kRFoot : kLFoot;
  const auto hip = static_cast<std::size_t>(k == 0 ? dof::kRHip : dof::kLHip);
  const JointDef& td = skel.joints[static_cast<std::size_t>(thigh)];
  const Segment& seg = skel.joints[static_cast<std::size_t>(foot)].segment;
  std::array<glm::mat4, kHumanJointCount> m;
  float gap = 0;
  bool sunk = false;
  for (int it = 0; it < 3; ++it) {
    LocalToModelJob fk{&skel, std::span<const float>(a.data(), a.size()), glm::vec3(0, pelvis_h, 0), m};
    fk.joint_mask = kLegJoints;
    if (!fk.Run()) return gap;
    const glm::mat4& fm = m[static_cast<std::size_t>(foot)];
    const glm::mat3 rot(fm);
    glm::vec3 n_local;
    const float dist = box_distance(seg, glm::transpose(rot) * (ball_ms - glm::vec3(fm[3])), &n_local);
    gap = dist - ball_r;
    // Short of the ball: on to it. Sunk deeper than kDeepInBallM: out to
    // the gap. Else left.
    if (it == 0) sunk = gap < -kDeepInBallM;
    if (sunk ? gap >= gap_m - 0.001f : gap <= gap_m + 0.001f) break;
    // The box's point nearest the ball, and where it should be.
    const glm::vec3 n = rot * n_local;
    const glm::vec3 near = ball_ms - n * dist;
    const glm::vec3 h(m[static_cast<std::size_t>(thigh)][3]);
    const glm::vec3 u = near - h, v = near + n * (gap - gap_m) - h;
    const glm::vec3 axis = glm::cross(u, v);
    const float sin_len = glm::length(axis);
    if (sin_len < 1e-6f) break;
    const float angle = pm::atan2(sin_len, glm::dot(u, v));
    // The thigh's local rotation turned about the hip: parent^-1 * S * (parent * local).
    const glm::mat3 parent(m[static_cast<std::size_t>(td.parent)]);
    const glm::mat3 turned = glm::transpose(parent) * axis_turn(axis / sin_len, angle) * glm::mat3(m[static_cast<std::size_t>(thigh)]);
    float deg[3];
    if (!joint_angles(td.dofs, turned, deg)) break;
    float next[3];
    for (std::size_t d = 0; d < 3; ++d) {
      next[d] = a[hip + d] + remainder_360(deg[d] - a[hip + d]);
      next[d] = std::clamp(next[d], td.limits[d][0], std::max(td.limits[d][0], td.limits[d][1]));
    }
    // Within the hip's turn from the last frame: as much of the way as that allows.
    float now[3] = {a[hip], a[hip + 1], a[hip + 2]};
    if (rotation_between(td.dofs, &last[hip], next) > cap_deg) {
      float lo = 0, hi = 1;
      for (int b = 0; b < 8; ++b) {
        const float mid = 0.5f * (lo + hi);
        float at[3];
        for (int d = 0; d < 3; ++d) at[d] = now[d] + (next[d] - now[d]) * mid;
        (rotation_between(td.dofs, &last[hip], at) > cap_deg ? hi : lo) = mid;
      }
      for (int d = 0; d < 3; ++d) next[d] = now[d] + (next[d] - now[d]) * lo;
    }
    if (next[0] == now[0] && next[1] == now[1] && next[2] == now[2]) break;
    for (std::size_t d = 0; d < 3; ++d) a[hip + d] = next[d];
  }
  return gap;
}

}  // namespace mc::anim
