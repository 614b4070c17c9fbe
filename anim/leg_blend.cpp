#include "anim/leg_blend.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "anim/body_frame.hpp"
#include "anim/local_to_model_job.hpp"
#include "anim/rough_sincos.hpp"
#include "anim/segment_distance.hpp"

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

// Rodrigues: the rotation by `angle` (rad) about unit axis `n`,
// cos I + (1 - cos) n n^T + sin [n]x.
glm::mat3 axis_rotation(const glm::vec3& n, float angle) {
  float sin_a = 0, cos_a = 1;
  pm::sincos(angle, sin_a, cos_a);
  glm::mat3 r = cos_a * glm::mat3(1.0f) + (1.0f - cos_a) * glm::outerProduct(n, n);
  r += sin_a * glm::mat3(0, n.z, -n.y, -n.z, 0, n.x, n.y, -n.x, 0);  // columns of [n]x
  return r;
}

// A joint's local transform (its rotation from `angles` + first_angle, at
// its offset from the parent).
glm::mat4 local_model(const std::vector<JointDef>& joints, int index, int first_angle, const float* angles) {
  const JointDef& d = joints[static_cast<std::size_t>(index)];
  glm::mat4 m(joint_rotation(d.dofs, angles + first_angle));
  m[3] = glm::vec4(d.offset_ls[0], d.offset_ls[1], d.offset_ls[2], 1.0f);
  return m;
}

// The root joint's model transform (body space, at the pose's height).
glm::mat4 root_model_of(const JointDef& root, const float* angles, float height) {
  glm::mat4 m(joint_rotation(root.dofs, angles));
  m[3] = glm::vec4(root.offset_ls[0], root.offset_ls[1] + height, root.offset_ls[2], 1.0f);
  return m;
}

// The lowest corner of a foot's box with model transform `m` (its joint's
// height when the segment is not a box).
float sole_height(const Segment& box, const glm::mat4& m) {
  float sole = m[3].y;
  if (box.shape == SegmentShape::Box)
    for (int c = 0; c < 8; ++c) {
      const glm::vec4 corner(box.center[0] + ((c & 1) ? 0.5f : -0.5f) * box.size[0],
                             box.center[1] + ((c & 2) ? 0.5f : -0.5f) * box.size[1],
                             box.center[2] + ((c & 4) ? 0.5f : -0.5f) * box.size[2], 1.0f);
      sole = std::min(sole, (m * corner).y);
    }
  return sole;
}

}  // namespace

LegBlend::LegBlend(const SkeletonDef& skeleton) : skeleton_(skeleton) {
  const auto& joints = skeleton.joints;
  std::vector<int> first(joints.size(), 0);
  for (std::size_t i = 1; i < joints.size(); ++i)
    first[i] = first[i - 1] + static_cast<int>(joints[i - 1].dofs.size());
  auto joint = [&](std::size_t i) {
    Joint j{static_cast<int>(i), first[i], static_cast<int>(joints[i].dofs.size())};
    const Segment& sg = joints[i].segment;
    if (sg.shape == SegmentShape::Box) {
      const glm::vec3 h(0.5f * sg.size[0], 0.5f * sg.size[1], 0.5f * sg.size[2]);
      const int axis = h.x >= h.y && h.x >= h.z ? 0 : h.y >= h.z ? 1 : 2;
      glm::vec3 e(0.0f);
      e[axis] = h[axis];
      const glm::vec3 c(sg.center[0], sg.center[1], sg.center[2]);
      j.box = true;
      j.line_from = c - e;
      j.line_to = c + e;
      j.half_width = std::max(h[(axis + 1) % 3], h[(axis + 2) % 3]);
    }
    return j;
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

LegBlend::Frames LegBlend::frames(const PlayerPose& pa, const PlayerPose& pb) const {
  Frames f;
  if (!ready()) return f;
  const auto& joints = skeleton_.joints;
  auto local = [&](const Joint& j, const float* angles) { return local_model(joints, j.index, j.first_angle, angles); };
  // Where a pose puts a foot: its ankle (field space) and its box's lowest corner.
  auto place = [&](const Leg& leg, const PlayerPose& p) {
    const glm::mat4 m = root_model_of(joints[0], p.angles.data(), p.z) * local(leg.thigh, p.angles.data()) *
                        local(leg.shin, p.angles.data()) * local(leg.foot, p.angles.data());
    return FootPlace{FieldOf{BodyFrame(p.x, p.y, p.heading)}.point(glm::vec3(m[3])),
                     sole_height(joints[static_cast<std::size_t>(leg.foot.index)].segment, m)};
  };
  for (std::size_t i = 0; i < 2; ++i) {
    const Leg& leg = leg_[i];
    const FootPlace fa = place(leg, pa), fb = place(leg, pb);
    f.place[i][0] = fa;
    f.place[i][1] = fb;
    // The ankle's travel about the root over the frame (field space).
    f.travel[i] = glm::length((fb.ankle - glm::vec3(pb.x, pb.z, pb.y)) - (fa.ankle - glm::vec3(pa.x, pa.z, pa.y)));
    // The thigh's turn over the frame (deg): the angle between its local
    // rotations in the two frames.
    const Joint& th = leg.thigh;
    const std::string& dofs = joints[static_cast<std::size_t>(th.index)].dofs;
    const glm::mat3 ra = joint_rotation(dofs, pa.angles.data() + th.first_angle);
    const glm::mat3 rb = joint_rotation(dofs, pb.angles.data() + th.first_angle);
    const float tr = ra[0][0] * rb[0][0] + ra[0][1] * rb[0][1] + ra[0][2] * rb[0][2] + ra[1][0] * rb[1][0] +
                     ra[1][1] * rb[1][1] + ra[1][2] * rb[1][2] + ra[2][0] * rb[2][0] + ra[2][1] * rb[2][1] +
                     ra[2][2] * rb[2][2];
    f.thigh_turn_deg[i] = pm::acos(std::clamp(0.5f * (tr - 1.0f), -1.0f, 1.0f)) / kDeg;
  }
  return f;
}

void LegBlend::apply(const PlayerPose& pa, const PlayerPose& pb, float t, PlayerPose& o, glm::vec3* feet_way) const {
  if (feet_way != nullptr) *feet_way = glm::vec3(0.0f);
  if (!ready() || t <= 0.0f || t >= 1.0f) return;
  apply(frames(pa, pb), t, o, feet_way);
}

void LegBlend::apply(const Frames& f, float t, PlayerPose& o, glm::vec3* feet_way) const {
  if (feet_way != nullptr) *feet_way = glm::vec3(0.0f);
  if (!ready() || t <= 0.0f || t >= 1.0f) return;
  const auto& joints = skeleton_.joints;
  auto local = [&](const Joint& j, const float* angles) { return local_model(joints, j.index, j.first_angle, angles); };
  auto root_model = [&](const float* angles, float height) { return root_model_of(joints[0], angles, height); };

  const FieldOf body{BodyFrame(o.x, o.y, o.heading)};
  float free[2] = {0, 0};  // keep_apart's share whatever the drawn sole (leg_blend.hpp)
  const float* travel = f.travel;
  // The step turns thighs alone: the root's and the shins' and feet's own
  // transforms are posed once for both parts.
  float* q = o.angles.data();
  Fixed fixed;
  fixed.pelvis = root_model(q, o.z);
  for (std::size_t i = 0; i < 2; ++i) {
    fixed.shin[i] = local(leg_[i].shin, q);
    fixed.foot[i] = local(leg_[i].foot, q);
  }
  for (std::size_t i = 0; i < 2; ++i) {
    const Leg& leg = leg_[i];
    const FootPlace& fa = f.place[i][0];
    const FootPlace& fb = f.place[i][1];
    const bool ca = fa.sole < kContactM, cb = fb.sole < kContactM;
    const bool in_air = !ca && !cb;
    free[i] = in_air ? 1.0f : ca && !cb ? t : !ca && cb ? 1.0f - t : 0.0f;
    if (in_air) continue;  // in the air in both: the blend's arc
    // The drawn pose's hip (the thigh joint) and ankle.
    const glm::mat4& pelvis = fixed.pelvis;
    const glm::mat4 thigh = pelvis * local(leg.thigh, q);
    const glm::vec3 hip(thigh[3]);
    const glm::vec3 ankle(thigh * fixed.shin[i] * fixed.foot[i][3]);
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
      // Across the grass it starts slowly (leaving) or ends slowly
      // (landing): t -/+ k t (1 - t) of its way (taken kAcrossWayM at
      // most), as a runner's foot lifts before it swings and is over its
      // spot before it lands; k no more than the ankle's travel about the
      // root leaves below kApartTravelM, which the ease adds to.
      float wx = 0, wz = 0;
      body.frame.dir_to_body(fb.ankle.x - fa.ankle.x, fb.ankle.z - fa.ankle.z, wx, wz);
      const float way = std::sqrt(wx * wx + wz * wz);
      if (way > 1e-4f) {
        const float taken = std::min(way, kAcrossWayM);
        const float k = std::min(kAcrossEase, std::max(0.0f, kApartTravelM - travel[i]) / taken);
        const float shift = (ca ? -k : k) * t * (1.0f - t) * taken / way;
        target.x += wx * shift;
        target.z += wz * shift;
      }
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
    const glm::mat3 swing = axis_rotation(axis / s, angle);
    turn_thigh(leg, pelvis, thigh, swing, q);
  }
  // How far each leg may turn out of the other's way (rad): growing from 0
  // at either frame at the rate its thigh's own turn over the frame leaves
  // below kApartSpeedDeg, so that the legs never turn faster than the
  // frames let them, and at the rate its ankle's travel about the root
  // leaves below kApartTravelM (a fast foot carried sideways reads as a
  // pop), up to kMaxApartDeg. `along`: the same for a turn that may carry
  // the ankle along its travel (the feet's, below), whose move adds to the
  // travel rather than in quadrature.
  float room[2], along[2];
  for (std::size_t i = 0; i < 2; ++i) {
    const float speed = f.thigh_turn_deg[i];
    // The turn's sideways move of the ankle (about kApartLeverM from the
    // hip) added to its travel stays within kApartTravelM a frame.
    const float sideways = std::sqrt(std::max(0.0f, kApartTravelM * kApartTravelM - travel[i] * travel[i]));
    const float ramp = std::min(t, 1.0f - t);
    room[i] = std::min({kMaxApartDeg * kDeg, std::max(0.0f, kApartSpeedDeg - speed) * kDeg * ramp,
                        sideways / kApartLeverM * ramp});
    along[i] = std::min(room[i], std::max(0.0f, kApartTravelM - travel[i]) / kApartLeverM * ramp);
  }
  keep_apart(free, room, along, fixed, o, feet_way);
}

void LegBlend::turn_thigh(const Leg& leg, const glm::mat4& pelvis, const glm::mat4& thigh, const glm::mat3& rotation,
                          float* q) const {
  // The thigh's new local rotation: parent^-1 * rotation * (parent * local).
  const glm::mat3 parent(pelvis);
  const glm::mat3 turned = glm::transpose(parent) * rotation * glm::mat3(thigh);
  const JointDef& td = skeleton_.joints[static_cast<std::size_t>(leg.thigh.index)];
  float deg[3];
  if (!joint_angles(td.dofs, turned, deg)) return;
  for (int k = 0; k < 3; ++k) {
    float& v_out = q[leg.thigh.first_angle + k];
    // The same turn, not one the other way round the circle.
    const float d = remainder_360(deg[k] - v_out);
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

LegBlend::Nearest LegBlend::nearest(const glm::mat4 thigh[2], const glm::mat4 shin[2], const glm::mat4 foot[2]) const {
  Nearest n;
  const std::pair<const Joint Leg::*, const glm::mat4*> pairs[] = {
      {&Leg::thigh, thigh}, {&Leg::shin, shin}, {&Leg::foot, foot}};
  for (const auto& [member, model] : pairs) {
    const Joint& j0 = leg_[0].*member;
    const Joint& j1 = leg_[1].*member;
    if (!j0.box || !j1.box) continue;
    const ClosestPoints c = closest_points(glm::vec3(model[0] * glm::vec4(j0.line_from, 1.0f)),
                                           glm::vec3(model[0] * glm::vec4(j0.line_to, 1.0f)),
                                           glm::vec3(model[1] * glm::vec4(j1.line_from, 1.0f)),
                                           glm::vec3(model[1] * glm::vec4(j1.line_to, 1.0f)));
    const float clear = c.distance - std::max(j0.half_width, j1.half_width);
    if (clear < n.clearance) {
      n.clearance = clear;
      n.feet = member == &Leg::foot;
      n.closest = c;
    }
  }
  return n;
}

glm::vec3 LegBlend::ankle(const PlayerPose& p, int i, float* sole) const {
  if (!ready()) {
    if (sole != nullptr) *sole = p.z;
    return glm::vec3(p.x, p.z, p.y);
  }
  const auto& joints = skeleton_.joints;
  const Leg& leg = leg_[static_cast<std::size_t>(i & 1)];
  const float* q = p.angles.data();
  const glm::mat4 m = root_model_of(joints[0], q, p.z) * local_model(joints, leg.thigh.index, leg.thigh.first_angle, q) *
                      local_model(joints, leg.shin.index, leg.shin.first_angle, q) *
                      local_model(joints, leg.foot.index, leg.foot.first_angle, q);
  if (sole != nullptr) *sole = sole_height(joints[static_cast<std::size_t>(leg.foot.index)].segment, m);
  return FieldOf{BodyFrame(p.x, p.y, p.heading)}.point(glm::vec3(m[3]));
}

float LegBlend::clearance(const PlayerPose& o) const {
  if (!ready()) return INFINITY;
  const auto& joints = skeleton_.joints;
  const float* q = o.angles.data();
  auto local = [&](const Joint& j) { return local_model(joints, j.index, j.first_angle, q); };
  // Both legs hang from the root joint, so how far apart they are does not
  // depend on the root's rotation or place: they are posed in its space.
  glm::mat4 thigh[2], shin[2], foot[2];
  for (std::size_t i = 0; i < 2; ++i) {
    thigh[i] = local(leg_[i].thigh);
    shin[i] = thigh[i] * local(leg_[i].shin);
    foot[i] = shin[i] * local(leg_[i].foot);
  }
  return nearest(thigh, shin, foot).clearance;
}

float LegBlend::rough_clearance(const float* a, const float* b, float t) const {
  if (!ready()) return INFINITY;
  const auto& joints = skeleton_.joints;
  // Each joint's dofs' sines and cosines, and how it carries a point into
  // its parent's space: its elementary rotations applied to the point,
  // last dof first (joint_rotation is R_dofs[0] R_dofs[1] ...), then its
  // offset. No matrices: the gate carries only the six ends of the three
  // segments' centre lines per leg.
  struct Carry {
    const char* axes = "";
    int n = 0;
    float s[3] = {0, 0, 0}, c[3] = {1, 1, 1};
    glm::vec3 offset{0.0f};
    glm::vec3 operator()(glm::vec3 p) const {
      for (int k = n - 1; k >= 0; --k) {
        const float sk = s[k], ck = c[k];
        if (axes[k] == 'x') p = glm::vec3(p.x, ck * p.y - sk * p.z, sk * p.y + ck * p.z);
        else if (axes[k] == 'y') p = glm::vec3(ck * p.x + sk * p.z, p.y, ck * p.z - sk * p.x);
        else p = glm::vec3(ck * p.x - sk * p.y, sk * p.x + ck * p.y, p.z);
      }
      return p + offset;
    }
  };
  bool known = true;
  auto carry = [&](const Joint& j) {
    const JointDef& d = joints[static_cast<std::size_t>(j.index)];
    Carry m;
    m.axes = d.dofs.c_str();
    m.n = std::min(j.dofs, 3);
    known = known && j.dofs <= 3;
    for (int k = 0; k < m.n; ++k) {
      const int i = j.first_angle + k;
      rough_sincos_deg(a[i] + (b[i] - a[i]) * t, m.s[k], m.c[k]);
      known = known && !std::isnan(m.s[k]);  // a NaN distance would pass unseen through std::min below
    }
    m.offset = glm::vec3(d.offset_ls[0], d.offset_ls[1], d.offset_ls[2]);
    return m;
  };
  glm::vec3 ends[3][2][2];  // [thigh, shin, foot][leg][from, to], in the root's space
  for (std::size_t i = 0; i < 2; ++i) {
    const Leg& leg = leg_[i];
    const Carry thigh = carry(leg.thigh), shin = carry(leg.shin), foot = carry(leg.foot);
    ends[0][i][0] = thigh(leg.thigh.line_from);
    ends[0][i][1] = thigh(leg.thigh.line_to);
    ends[1][i][0] = thigh(shin(leg.shin.line_from));
    ends[1][i][1] = thigh(shin(leg.shin.line_to));
    ends[2][i][0] = thigh(shin(foot(leg.foot.line_from)));
    ends[2][i][1] = thigh(shin(foot(leg.foot.line_to)));
  }
  float clear = INFINITY;
  const Joint Leg::*members[3] = {&Leg::thigh, &Leg::shin, &Leg::foot};
  for (int s = 0; s < 3; ++s) {
    const Joint& j0 = leg_[0].*members[s];
    const Joint& j1 = leg_[1].*members[s];
    if (!j0.box || !j1.box) continue;
    const float d = closest_points(ends[s][0][0], ends[s][0][1], ends[s][1][0], ends[s][1][1]).distance;
    clear = std::min(clear, d - std::max(j0.half_width, j1.half_width));
  }
  return known && std::isfinite(clear) ? clear : NAN;
}

void LegBlend::keep_apart(const float free[2], float room[2], float along[2], const Fixed& fixed, PlayerPose& o,
                          glm::vec3* feet_way) const {
  const auto& joints = skeleton_.joints;
  float* q = o.angles.data();
  auto local = [&](const Joint& j) { return local_model(joints, j.index, j.first_angle, q); };
  const glm::mat4& pelvis = fixed.pelvis;
  // Each leg as last posed; a leg is posed again only after its thigh
  // turned (the same products of the same transforms: the same bits as
  // posing both legs every round, for a fifth fewer of the step's
  // instructions).
  glm::mat4 thigh[2], shin[2], foot[2];
  float sole[2] = {0, 0};
  bool stale[2] = {true, true};
  // kApartRounds times: each round takes up what the turn before left (a
  // turn is a rotation, and the nearest points move as it goes).
  for (int round = 0; round < kApartRounds; ++round) {
    float share[2];
    for (std::size_t i = 0; i < 2; ++i) {
      if (stale[i]) {
        thigh[i] = pelvis * local(leg_[i].thigh);
        shin[i] = thigh[i] * fixed.shin[i];
        foot[i] = shin[i] * fixed.foot[i];
        sole[i] = sole_height(joints[static_cast<std::size_t>(leg_[i].foot.index)].segment, foot[i]);
        stale[i] = false;
      }
      // A foot on the grass stays where the first part left it; one in the
      // air moves freely from twice that height (between: in proportion,
      // so that the turn grows smoothly as the foot rises). A foot leaving
      // or landing moves at least by its `free` share, however low the
      // blend draws it: it is on its way, not planted (a swing that lands
      // beside the other foot and passes through it late in the frame;
      // 2026-11-29, legs too close at 60 Hz 18 -> 9 player-frames).
      share[i] = std::max(free[i], std::clamp((sole[i] - kContactM) / kContactM, 0.0f, 1.0f));
    }
    const float shares = share[0] + share[1];
    if (shares <= 0.0f) return;
    const Nearest near = nearest(thigh, shin, foot);
    const float shortfall = kApartM - near.clearance;
    const bool feet = near.feet;
    const ClosestPoints& closest = near.closest;
    if (shortfall <= 0.0f) return;
    // Each leg in the air turns at the hip by its share of the shortfall:
    // the angle that moves its nearest point that far away from the other
    // leg's. Thighs and shins move out, away from the other hip. Feet move
    // apart along the line between them: they pass each other front to
    // back as well as side to side, and moved out from the other hip one
    // may slide along the other or even towards it (a real case:
    // LegBlend.FeetThatMeetInTheBlendPartAlongTheLineBetweenThem). On the
    // two full games, feet drawn too close at 60 Hz in four rounds (before
    // the ease across the grass above): 46 and 39 player-frames moving
    // out, 30 and 31 along the line between their nearest points. Each
    // foot now moves its middle away from the other foot's centre line:
    // the nearest points jump from end to end of a centre line as one foot
    // passes the other, and the push turned with them within a frame (game
    // 1 seq 8801: the feet pushed one way, then the other, turning the
    // thighs into each other); a middle and its nearest point on a line
    // move as smoothly as the legs. (The line between the two middles
    // moves smoothly too, but the check then cleared fewer of the crossing
    // swings of drawn_leg_clearance_test: anim/README.md, session 37.)
    const glm::vec3 hip[2] = {glm::vec3(thigh[0][3]), glm::vec3(thigh[1][3])};
    glm::vec3 gap[2];
    bool between_feet = feet;
    if (feet) {
      glm::vec3 from[2], to[2];
      for (std::size_t i = 0; i < 2; ++i) {
        from[i] = glm::vec3(foot[i] * glm::vec4(leg_[i].foot.line_from, 1.0f));
        to[i] = glm::vec3(foot[i] * glm::vec4(leg_[i].foot.line_to, 1.0f));
      }
      for (std::size_t i = 0; i < 2; ++i) {
        const glm::vec3 middle = 0.5f * (from[i] + to[i]);
        gap[i] = middle - closest_points(middle, middle, from[1 - i], to[1 - i]).on_second;
        between_feet = between_feet && glm::length(gap[i]) >= 1e-3f;
      }
    }
    if (round == 0 && between_feet && feet_way != nullptr) *feet_way = gap[0];
    for (std::size_t i = 0; i < 2; ++i) {
      if (share[i] <= 0.0f) continue;
      const glm::vec3 lever = (i == 0 ? closest.on_first : closest.on_second) - hip[i];
      const glm::vec3 away = between_feet ? gap[i] : hip[i] - hip[1 - i];
      const float width = glm::length(away);
      if (width < 1e-4f) continue;
      const glm::vec3 axis = glm::cross(lever, away / width);
      const float reach = glm::length(axis);  // travel away per radian
      if (reach < 1e-3f) continue;
      const float angle = std::min(shortfall * share[i] / shares / reach, between_feet ? along[i] : room[i]);
      if (angle <= 0.0f) continue;
      room[i] -= angle;
      along[i] -= angle;
      turn_thigh(leg_[i], pelvis, thigh[i], axis_rotation(axis / reach, angle), q);
      stale[i] = true;
    }
  }
}

}  // namespace mc::anim
