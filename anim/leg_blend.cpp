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

// Where one pose puts a foot: the ankle (the foot joint's origin) and the
// foot's forward and up axes, in field space as (x, height, y).
struct FootPlace {
  glm::vec3 ankle{0.0f}, forward{1, 0, 0}, up{0, 1, 0};
  float sole = 0;  // the foot box's lowest corner above the grass (m)
};

// Body space (X forward, Y up, Z right) of a player at (x, y, heading) ->
// field space written as (x, height, y).
struct FieldOf {
  BodyFrame frame;
  glm::vec3 point(const glm::vec3& b) const {
    float fx = 0, fy = 0;
    frame.to_field(b.x, b.z, fx, fy);
    return {fx, b.y, fy};
  }
  glm::vec3 direction(const glm::vec3& b) const {
    return {b.x * frame.c - b.z * frame.s, b.y, b.x * frame.s + b.z * frame.c};
  }
  glm::vec3 to_body_point(const glm::vec3& f) const {
    float bx = 0, bz = 0;
    frame.to_body(f.x, f.z, bx, bz);
    return {bx, f.y, bz};
  }
  glm::vec3 to_body_direction(const glm::vec3& f) const {
    return {f.x * frame.c + f.z * frame.s, f.y, -f.x * frame.s + f.z * frame.c};
  }
};

constexpr float kStepDeg = 0.5f;       // finite-difference step
// (m/deg)^2. A leg near straight cannot move its ankle along itself: the
// damping keeps it from flailing after a target it cannot reach.
constexpr float kDamping2 = 5e-6f;
// The re-aiming corrects the blend's small error; it never turns a joint
// far from the blended angle (a target out of reach is not chased).
constexpr float kMaxStepDeg = 4.0f;
constexpr float kMaxFixDeg = 12.0f;
constexpr float kReachedM = 0.0005f;   // close enough: half a millimetre
constexpr int kReachIterations = 4;
// A foot is on the grass when its box's lowest corner is this low (the
// height at which a viewer sees it touch; anim-quality's contact).
constexpr float kContactM = 0.03f;
// Both frames on the grass and this close: one stance (a foot cannot lift
// and land again within 50 ms).
constexpr float kSameStanceM = 0.3f;
constexpr int kSoleIterations = 2;

}  // namespace

LegBlend::LegBlend(const SkeletonDef& skeleton, bool lift_and_land)
    : skeleton_(skeleton), lift_and_land_(lift_and_land) {
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
    if (leg.thigh.dofs > 3 || leg.shin.dofs > 1 || leg.foot.dofs > 2) continue;
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
  if (!ready()) return;
  const auto& joints = skeleton_.joints;
  const JointDef& root = joints[0];
  auto local = [&](const Joint& j, const float* angles) {
    const JointDef& d = joints[static_cast<std::size_t>(j.index)];
    glm::mat4 m(joint_rotation(d.dofs, angles + j.first_angle));
    m[3] = glm::vec4(d.offset_ls[0], d.offset_ls[1], d.offset_ls[2], 1.0f);
    return m;
  };
  // The foot joint's model transform (body space; the root at the pose's height).
  auto foot_model = [&](const Leg& leg, const float* angles, float height) {
    glm::mat4 m(joint_rotation(root.dofs, angles));
    m[3] = glm::vec4(root.offset_ls[0], root.offset_ls[1] + height, root.offset_ls[2], 1.0f);
    return m * local(leg.thigh, angles) * local(leg.shin, angles) * local(leg.foot, angles);
  };
  auto place = [&](const Leg& leg, const PlayerPose& p) {
    const FieldOf f{BodyFrame(p.x, p.y, p.heading)};
    const glm::mat4 m = foot_model(leg, p.angles.data(), p.z);
    const Segment& box = joints[static_cast<std::size_t>(leg.foot.index)].segment;
    float sole = m[3].y;
    if (box.shape == SegmentShape::Box)
      for (int c = 0; c < 8; ++c) {
        const glm::vec4 corner(box.center[0] + ((c & 1) ? 0.5f : -0.5f) * box.size[0],
                               box.center[1] + ((c & 2) ? 0.5f : -0.5f) * box.size[1],
                               box.center[2] + ((c & 4) ? 0.5f : -0.5f) * box.size[2], 1.0f);
        sole = std::min(sole, (m * corner).y);
      }
    return FootPlace{f.point(glm::vec3(m[3])), f.direction(glm::vec3(m[0])), f.direction(glm::vec3(m[1])), sole};
  };
  auto clamp_dof = [&](const Joint& j, int k, float v) {
    const auto& lim = joints[static_cast<std::size_t>(j.index)].limits;
    if (static_cast<std::size_t>(k) < lim.size()) v = std::clamp(v, lim[static_cast<std::size_t>(k)][0], lim[static_cast<std::size_t>(k)][1]);
    return v;
  };

  const FieldOf body{BodyFrame(o.x, o.y, o.heading)};
  for (const Leg& leg : leg_) {
    const FootPlace fa = place(leg, pa), fb = place(leg, pb);
    // A foot on the grass in both frames keeps to the line between its two
    // places. With lift_and_land, a leaving foot also stays until its sole
    // clears the grass and a landing one arrives before it touches. A foot
    // in the air in both keeps the angle blend's arc, which a straight line
    // would cut short (and turn the hip far from the frames' motion).
    const bool ca = fa.sole < kContactM, cb = fb.sole < kContactM;
    float across = t;  // how far along the way the ankle is over the grass
    if (ca && cb) {
      if (glm::length(fb.ankle - fa.ankle) >= kSameStanceM) continue;
    } else if (!lift_and_land_ || (!ca && !cb)) {
      continue;
    } else if (ca) {  // lift-off: on the spot until the sole clears
      const float clear = std::clamp((kContactM - fa.sole) / std::max(1e-4f, fb.sole - fa.sole), 0.0f, 1.0f);
      across = t <= clear ? 0.0f : (t - clear) / std::max(1e-4f, 1.0f - clear);
    } else {  // touch-down: there before the sole reaches the grass
      const float touch = std::clamp((fa.sole - kContactM) / std::max(1e-4f, fa.sole - fb.sole), 0.0f, 1.0f);
      across = t >= touch ? 1.0f : t / std::max(1e-4f, touch);
    }
    glm::vec3 way = fa.ankle + (fb.ankle - fa.ankle) * across;
    way.y = fa.ankle.y + (fb.ankle.y - fa.ankle.y) * t;
    const glm::vec3 ankle = body.to_body_point(way);
    const glm::vec3 forward = glm::normalize(body.to_body_direction(fa.forward + (fb.forward - fa.forward) * t));
    const glm::vec3 up = glm::normalize(body.to_body_direction(fa.up + (fb.up - fa.up) * t));

    // The ankle onto its line: thigh and shin dofs by damped least squares.
    float* q = o.angles.data();
    int idx[4];
    const Joint* owner[4];
    int n = 0;
    for (int k = 0; k < leg.thigh.dofs; ++k) owner[n] = &leg.thigh, idx[n++] = leg.thigh.first_angle + k;
    for (int k = 0; k < leg.shin.dofs; ++k) owner[n] = &leg.shin, idx[n++] = leg.shin.first_angle + k;
    float blended[4];
    for (int c = 0; c < n; ++c) blended[c] = q[idx[c]];
    for (int it = 0; it < kReachIterations; ++it) {
      const glm::vec3 at(foot_model(leg, q, o.z)[3]);
      const glm::vec3 r = ankle - at;
      if (glm::length(r) < kReachedM) break;
      glm::vec3 jac[4];
      for (int c = 0; c < n; ++c) {
        const float keep = q[idx[c]];
        q[idx[c]] = keep + kStepDeg;
        jac[c] = (glm::vec3(foot_model(leg, q, o.z)[3]) - at) / kStepDeg;
        q[idx[c]] = keep;
      }
      glm::mat3 jjt(kDamping2);  // J J^T + lambda^2 I
      for (int c = 0; c < n; ++c) jjt += glm::outerProduct(jac[c], jac[c]);
      const glm::vec3 y = glm::inverse(jjt) * r;
      for (int c = 0; c < n; ++c) {
        const int k = idx[c] - owner[c]->first_angle;
        const float step = std::clamp(glm::dot(jac[c], y), -kMaxStepDeg, kMaxStepDeg);
        const float v = std::clamp(q[idx[c]] + step, blended[c] - kMaxFixDeg, blended[c] + kMaxFixDeg);
        q[idx[c]] = clamp_dof(*owner[c], k, v);
      }
    }

    // The sole: the foot's dofs bring its axes nearest the blended ones.
    for (int it = 0; it < kSoleIterations && leg.foot.dofs > 0; ++it) {
      const glm::mat4 m = foot_model(leg, q, o.z);
      const glm::vec3 ef = forward - glm::vec3(m[0]), eu = up - glm::vec3(m[1]);
      glm::vec3 jf[2], ju[2];
      for (int c = 0; c < leg.foot.dofs; ++c) {
        float& v = q[leg.foot.first_angle + c];
        const float keep = v;
        v = keep + kStepDeg;
        const glm::mat4 mm = foot_model(leg, q, o.z);
        v = keep;
        jf[c] = (glm::vec3(mm[0]) - glm::vec3(m[0])) / kStepDeg;
        ju[c] = (glm::vec3(mm[1]) - glm::vec3(m[1])) / kStepDeg;
      }
      // Normal equations of the 6 x dofs system (at most 2 x 2).
      float a00 = kDamping2 + glm::dot(jf[0], jf[0]) + glm::dot(ju[0], ju[0]);
      float g0 = glm::dot(jf[0], ef) + glm::dot(ju[0], eu);
      if (leg.foot.dofs == 1) {
        q[leg.foot.first_angle] = clamp_dof(leg.foot, 0, q[leg.foot.first_angle] + g0 / a00);
        continue;
      }
      const float a01 = glm::dot(jf[0], jf[1]) + glm::dot(ju[0], ju[1]);
      const float a11 = kDamping2 + glm::dot(jf[1], jf[1]) + glm::dot(ju[1], ju[1]);
      const float g1 = glm::dot(jf[1], ef) + glm::dot(ju[1], eu);
      const float det = a00 * a11 - a01 * a01;
      if (std::abs(det) < 1e-12f) break;
      q[leg.foot.first_angle] = clamp_dof(leg.foot, 0, q[leg.foot.first_angle] + (a11 * g0 - a01 * g1) / det);
      q[leg.foot.first_angle + 1] = clamp_dof(leg.foot, 1, q[leg.foot.first_angle + 1] + (a00 * g1 - a01 * g0) / det);
    }
  }
}

}  // namespace mc::anim
