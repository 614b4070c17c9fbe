#include "anim/tools/posed_body.hpp"

#include <algorithm>
#include <cmath>

#include <glm/vec4.hpp>

#include "anim/local_to_model_job.hpp"
#include "anim/segment_distance.hpp"
#include "anim/tools/close_up_metrics.hpp"

namespace mc::anim::tools::posed {
namespace {

constexpr float kRadToDeg = 57.29577951308232f;

void centreline(const Rig& rig, const Geom& g, int j, glm::vec3& p, glm::vec3& q) {
  const Box& b = rig.box[static_cast<std::size_t>(j)];
  glm::vec3 e(0);
  e[b.axis] = b.h[b.axis];
  const glm::mat4& w = g.world[static_cast<std::size_t>(j)];
  p = glm::vec3(w * glm::vec4(b.c - e, 1.0f));
  q = glm::vec3(w * glm::vec4(b.c + e, 1.0f));
}

}  // namespace

Rig::Rig(const SkeletonDef& s) {
  auto find = [&](const char* n) { return s.find(n); };
  foot[0] = find("r_foot"); foot[1] = find("l_foot");
  thigh[0] = find("r_thigh"); thigh[1] = find("l_thigh");
  shin[0] = find("r_shin"); shin[1] = find("l_shin");
  hand[0] = find("r_hand"); hand[1] = find("l_hand");
  pelvis = find("pelvis"); torso = find("torso");
  int d = 0;
  for (const JointDef& j : s.joints) {
    const std::string& n = j.name;
    auto has = [&](const char* w) { return n.find(w) != std::string::npos; };
    group.push_back(has("thigh") || has("shin") || has("foot") ? kLegs
                    : has("arm") || has("hand")                 ? kArms
                    : has("neck") || has("head")                ? kHead
                                                                : kTrunk);
    first_dof.push_back(d);
    d += static_cast<int>(j.dofs.size());
    Box b;
    if (j.segment.shape == SegmentShape::Box) {
      b.valid = true;
      b.c = glm::vec3(j.segment.center[0], j.segment.center[1], j.segment.center[2]);
      b.h = 0.5f * glm::vec3(j.segment.size[0], j.segment.size[1], j.segment.size[2]);
      b.axis = b.h.x >= b.h.y && b.h.x >= b.h.z ? 0 : b.h.y >= b.h.z ? 1 : 2;
      b.half_width = std::max(b.h[(b.axis + 1) % 3], b.h[(b.axis + 2) % 3]);
    }
    box.push_back(b);
  }
}

void pose(const SkeletonDef& s, const Rig& rig, const PlayerPose& p, Geom& g) {
  const std::size_t n = s.joints.size();
  g.world.resize(n);
  g.rot.resize(n);
  g.active = (p.state & state_bits::kStand) != 0;
  g.x = p.x;
  g.y = p.y;
  const float h = p.heading * (3.14159265358979f / 180.0f);
  const float c = std::cos(h), sn = std::sin(h);
  glm::mat4 field(1.0f);
  field[0] = glm::vec4(c, 0, sn, 0);
  field[2] = glm::vec4(-sn, 0, c, 0);
  field[3] = glm::vec4(p.x, 0, p.y, 1);
  for (std::size_t j = 0; j < n; ++j) {
    const JointDef& jd = s.joints[j];
    const glm::mat3 r = joint_rotation(jd.dofs, &p.angles[static_cast<std::size_t>(rig.first_dof[j])]);
    glm::mat4 local(r);
    local[3] = glm::vec4(jd.offset_ls[0], jd.offset_ls[1], jd.offset_ls[2], 1.0f);
    if (jd.parent < 0) {
      local[3] += glm::vec4(0, p.z, 0, 0);
      g.world[j] = field * local;
      g.rot[j] = glm::mat3(field) * r;
    } else {
      g.world[j] = g.world[static_cast<std::size_t>(jd.parent)] * local;
      g.rot[j] = r;
    }
  }
  for (int f = 0; f < 2; ++f) {
    FootGeom& fg = g.feet[f];
    fg = FootGeom{};
    const int j = rig.foot[f];
    if (j < 0 || !rig.box[static_cast<std::size_t>(j)].valid) continue;
    const Box& b = rig.box[static_cast<std::size_t>(j)];
    const glm::mat4& w = g.world[static_cast<std::size_t>(j)];
    glm::vec3 corner[4];
    float hgt[4];
    int k = 0;
    for (float sx : {-1.0f, 1.0f})
      for (float sz : {-1.0f, 1.0f}) {
        corner[k] = b.c + glm::vec3(sx * b.h.x, -b.h.y, sz * b.h.z);
        hgt[k] = (w * glm::vec4(corner[k], 1.0f)).y;
        fg.lowest = std::min(fg.lowest, hgt[k]);
        ++k;
      }
    glm::vec3 sum(0);
    float wsum = 0;
    for (int i = 0; i < 4; ++i) {
      const float wt = std::max(0.0f, 1.0f - (hgt[i] - fg.lowest) / 0.01f);
      sum += wt * corner[i];
      wsum += wt;
    }
    fg.contact_ls = sum / wsum;
    fg.grounded = fg.lowest < close_up::kGroundedBelowM;
  }
}

float rotation_deg(const glm::mat3& a, const glm::mat3& b) {
  float tr = 0;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) tr += a[i][k] * b[i][k];
  return std::acos(std::clamp(0.5f * (tr - 1.0f), -1.0f, 1.0f)) * kRadToDeg;
}

float box_sd(const Box& b, const glm::vec3& p) {
  const glm::vec3 q = glm::abs(p - b.c) - b.h;
  const glm::vec3 out = glm::max(q, glm::vec3(0));
  return std::sqrt(glm::dot(out, out)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
}

float clearance(const Rig& rig, const Geom& g, int a, int b) {
  if (a < 0 || b < 0 || !rig.box[static_cast<std::size_t>(a)].valid || !rig.box[static_cast<std::size_t>(b)].valid)
    return 1;
  glm::vec3 p1, q1, p2, q2;
  centreline(rig, g, a, p1, q1);
  centreline(rig, g, b, p2, q2);
  const float hw = std::max(rig.box[static_cast<std::size_t>(a)].half_width, rig.box[static_cast<std::size_t>(b)].half_width);
  return segment_distance(p1, q1, p2, q2) - hw;
}

float hand_depth(const Rig& rig, const Geom& g, int hand, int body) {
  if (hand < 0 || body < 0) return 0;
  const Box& hb = rig.box[static_cast<std::size_t>(hand)];
  const Box& bb = rig.box[static_cast<std::size_t>(body)];
  if (!hb.valid || !bb.valid) return 0;
  const glm::mat4& wh = g.world[static_cast<std::size_t>(hand)];
  const glm::mat4& wb = g.world[static_cast<std::size_t>(body)];
  const glm::vec3 ch(wh * glm::vec4(hb.c, 1.0f)), cb(wb * glm::vec4(bb.c, 1.0f));
  if (glm::length(ch - cb) > glm::length(hb.h) + glm::length(bb.h)) return 0;
  // Rigid transforms: the inverse rotation is the transpose.
  const glm::mat3 rb_t = glm::transpose(glm::mat3(wb));
  const glm::vec3 tb(wb[3]);
  float depth = 0;
  for (float sx : {-1.0f, 0.0f, 1.0f})
    for (float sy : {-1.0f, -0.5f, 0.0f, 0.5f, 1.0f})
      for (float sz : {-1.0f, 0.0f, 1.0f}) {
        const glm::vec3 pw(wh * glm::vec4(hb.c + glm::vec3(sx, sy, sz) * hb.h, 1.0f));
        depth = std::max(depth, -box_sd(bb, rb_t * (pw - tb)));
      }
  return depth;
}

}  // namespace mc::anim::tools::posed
