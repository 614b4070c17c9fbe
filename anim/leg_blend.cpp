#include "anim/leg_blend.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include <glm/glm.hpp>

#include "anim/body_frame.hpp"
#include "anim/local_to_model_job.hpp"

namespace mc::anim {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool has_any(const std::string& s, std::initializer_list<const char*> words) {
  return std::any_of(words.begin(), words.end(), [&](const char* w) { return s.find(w) != std::string::npos; });
}

// -1 left, +1 right, 0 neither (a name such as "r_thigh", "RightUpLeg", "thigh.L").
int side_of(const std::string& n) {
  if (n.rfind("l_", 0) == 0 || n.rfind("left", 0) == 0 || n.ends_with("_l") || n.ends_with(".l")) return -1;
  if (n.rfind("r_", 0) == 0 || n.rfind("right", 0) == 0 || n.ends_with("_r") || n.ends_with(".r")) return 1;
  return 0;
}

// Body space (X forward, Y up, Z right) of a player at (x, y, heading) ->
// field space written as (x, height, y), and back.
struct FieldOf {
  BodyFrame frame;
  glm::vec3 point(const glm::vec3& b) const {
    float fx = 0, fy = 0;
    frame.to_field(b.x, b.z, fx, fy);
    return {fx, b.y, fy};
  }
  glm::vec3 to_body_point(const glm::vec3& f) const {
    float bx = 0, bz = 0;
    frame.to_body(f.x, f.z, bx, bz);
    return {bx, f.y, bz};
  }
};

// Where one pose puts a foot.
struct FootPlace {
  glm::vec3 ankle{0.0f};  // field space (x, height, y)
  float sole = 0;         // the foot box's lowest corner above the grass (m)
};

}  // namespace

LegBlend::LegBlend(const SkeletonDef& skeleton) : skeleton_(skeleton) {
  const auto& joints = skeleton.joints;
  std::vector<int> first(joints.size(), 0);
  for (std::size_t i = 1; i < joints.size(); ++i)
    first[i] = first[i - 1] + static_cast<int>(joints[i - 1].dofs.size());
  auto joint = [&](std::size_t i) {
    return Joint{static_cast<int>(i), first[i], static_cast<int>(joints[i].dofs.size())};
  };
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const std::string n = lower(joints[i].name);
    const int side = side_of(n);
    if (side == 0 || !has_any(n, {"thigh", "upleg", "hip"}) || joints[i].parent != 0) continue;
    float probe[3];
    if (!joint_angles(joints[i].dofs, glm::mat3(1.0f), probe)) continue;
    // The chain below it: the shin is the thigh's only child named so, the
    // foot the shin's.
    Leg leg;
    leg.thigh = joint(i);
    for (std::size_t k = i + 1; k < joints.size(); ++k) {
      const std::string m = lower(joints[k].name);
      if (leg.shin.index < 0 && joints[k].parent == static_cast<int>(i) && has_any(m, {"shin", "knee", "calf", "leg"}))
        leg.shin = joint(k);
      else if (leg.shin.index >= 0 && joints[k].parent == leg.shin.index && has_any(m, {"foot", "ankle"}))
        leg.foot = joint(k);
    }
    if (leg.shin.index < 0 || leg.foot.index < 0) continue;
    if (legs_ < 2) leg_[static_cast<std::size_t>(legs_++)] = leg;
  }
  if (legs_ != 2) legs_ = 0;
}

void LegBlend::apply(const PoseFrame& a, const PoseFrame& b, float t, PoseFrame& out, float teleport_m) const {
  if (!ready() || t <= 0.0f || t >= 1.0f) return;
  for (std::size_t i = 0; i < kMaxPlayers; ++i) {
    const PlayerPose& pa = a.players[i];
    const PlayerPose& pb = b.players[i];
    if (pa.side == Side::Neutral || pb.side != pa.side || pb.unum != pa.unum) continue;
    if (pm::hypot(pb.x - pa.x, pb.y - pa.y) >= teleport_m) continue;
    apply(pa, pb, t, out.players[i]);
  }
}

void LegBlend::apply(const PlayerPose& pa, const PlayerPose& pb, float t, PlayerPose& o) const {
  if (!ready() || t <= 0.0f || t >= 1.0f) return;
  const auto& joints = skeleton_.joints;
  const JointDef& root = joints[0];
  auto local = [&](const Joint& j, const float* angles) {
    const JointDef& d = joints[static_cast<std::size_t>(j.index)];
    glm::mat4 m(joint_rotation(d.dofs, angles + j.first_angle));
    m[3] = glm::vec4(d.offset_ls[0], d.offset_ls[1], d.offset_ls[2], 1.0f);
    return m;
  };
  // The root joint's model transform (body space, at the pose's height).
  auto root_model = [&](const float* angles, float height) {
    glm::mat4 m(joint_rotation(root.dofs, angles));
    m[3] = glm::vec4(root.offset_ls[0], root.offset_ls[1] + height, root.offset_ls[2], 1.0f);
    return m;
  };
  // Where a pose puts a foot: its ankle (field space) and its box's lowest corner.
  auto place = [&](const Leg& leg, const PlayerPose& p) {
    const glm::mat4 m = root_model(p.angles.data(), p.z) * local(leg.thigh, p.angles.data()) *
                        local(leg.shin, p.angles.data()) * local(leg.foot, p.angles.data());
    const Segment& box = joints[static_cast<std::size_t>(leg.foot.index)].segment;
    float sole = m[3].y;
    if (box.shape == SegmentShape::Box)
      for (int c = 0; c < 8; ++c) {
        const glm::vec4 corner(box.center[0] + ((c & 1) ? 0.5f : -0.5f) * box.size[0],
                               box.center[1] + ((c & 2) ? 0.5f : -0.5f) * box.size[1],
                               box.center[2] + ((c & 4) ? 0.5f : -0.5f) * box.size[2], 1.0f);
        sole = std::min(sole, (m * corner).y);
      }
    return FootPlace{FieldOf{BodyFrame(p.x, p.y, p.heading)}.point(glm::vec3(m[3])), sole};
  };

  const FieldOf body{BodyFrame(o.x, o.y, o.heading)};
  for (const Leg& leg : leg_) {
    const FootPlace fa = place(leg, pa), fb = place(leg, pb);
    const bool ca = fa.sole < kContactM, cb = fb.sole < kContactM;
    if (!ca && !cb) continue;  // in the air in both: the blend's arc
    // The drawn pose's hip (the thigh joint) and ankle.
    float* q = o.angles.data();
    const glm::mat4 pelvis = root_model(q, o.z);
    const glm::mat4 thigh = pelvis * local(leg.thigh, q);
    const glm::vec3 hip(thigh[3]);
    const glm::vec3 ankle(thigh * local(leg.shin, q) * local(leg.foot, q)[3]);
    glm::vec3 target = ankle;
    if (ca && cb) {
      // One stance: across the grass, on the line between its two places.
      if (glm::length(fb.ankle - fa.ankle) >= kSameStanceM) continue;
      target = body.to_body_point(fa.ankle + (fb.ankle - fa.ankle) * t);
      target.y = ankle.y;
    } else {
      // Leaving (on the grass in a) or landing (in b): the sole's height
      // eases out of or into the grass; the blend gives it t of the way.
      const float e = ca ? 1.0f - (1.0f - t) * (1.0f - t) : t * t;
      target.y += (fb.sole - fa.sole) * (e - t);  // >= 0 either way
    }
    // Swing the leg about the hip: the rotation taking the ankle's direction
    // from the hip to the target's, no more than kMaxSwingDeg.
    const glm::vec3 from = ankle - hip, to = target - hip;
    const float lf = glm::length(from), lt = glm::length(to);
    if (lf < 1e-4f || lt < 1e-4f) continue;
    const glm::vec3 u = from / lf, v = to / lt;
    const glm::vec3 axis = glm::cross(u, v);
    const float s = glm::length(axis);
    if (s < 1e-6f) continue;
    const float angle = std::min(pm::atan2(s, glm::dot(u, v)), kMaxSwingDeg * kDeg);
    // Rodrigues: cos I + (1 - cos) n n^T + sin [n]x.
    const glm::vec3 n = axis / s;
    float sin_a = 0, cos_a = 1;
    pm::sincos(angle, sin_a, cos_a);
    glm::mat3 swing = cos_a * glm::mat3(1.0f) + (1.0f - cos_a) * glm::outerProduct(n, n);
    swing += sin_a * glm::mat3(0, n.z, -n.y, -n.z, 0, n.x, n.y, -n.x, 0);  // columns of [n]x
    // The thigh's new local rotation: parent^-1 * swing * (parent * local).
    const glm::mat3 parent(pelvis);
    const glm::mat3 turned = glm::transpose(parent) * swing * glm::mat3(thigh);
    const JointDef& td = joints[static_cast<std::size_t>(leg.thigh.index)];
    float deg[3];
    if (!joint_angles(td.dofs, turned, deg)) continue;
    for (int k = 0; k < 3; ++k) {
      float& v_out = q[leg.thigh.first_angle + k];
      // The same turn, not one the other way round the circle.
      const float d = std::remainder(deg[k] - v_out, 360.0f);
      float next = v_out + d;
      if (static_cast<std::size_t>(k) < td.limits.size()) {
        // A hello's limit given upside down is read as the quantizer reads
        // it (its top no lower than its bottom), never passed to std::clamp.
        const auto& lim = td.limits[static_cast<std::size_t>(k)];
        next = std::min(std::max(next, lim[0]), std::max(lim[0], lim[1]));
      }
      v_out = next;
    }
  }
}

}  // namespace mc::anim
