#include "anim/mocap/mocap_motion_source.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "anim/body_frame.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/mocap/graph_steer_job.hpp"
#include "anim/mocap/retarget_job.hpp"

namespace mc::anim::mocap {

MocapMotionSource::MocapMotionSource(std::vector<MocapClip> kicks) {
  for (MocapClip& c : kicks) {
    if (c.frames < 2 || !(c.frame_time > 0)) continue;
    Kick k;
    k.contact = kick_contact_frame(c, true);
    k.clip = std::move(c);
    // Keep only clips the retargeting accepts (the joint names it needs).
    std::array<float, dof::kCount> angles{};
    float pelvis = 0;
    MocapRetargetJob job;
    job.clip = &k.clip;
    job.frame = static_cast<float>(k.contact);
    job.angles = angles;
    job.pelvis_height = &pelvis;
    if (job.Validate()) kicks_.push_back(std::move(k));
  }
}

MocapMotionSource::MocapMotionSource(std::vector<MocapClip> kicks, MotionGraph graph, std::vector<MocapClip> graph_clips,
                                     int start_node)
    : MocapMotionSource(std::move(kicks)) {
  graph_ = std::move(graph);
  graph_clips_ = std::move(graph_clips);
  bool ok = start_node >= 0 && start_node < graph_.size() && graph_clips_.size() == graph_.clip_names.size();
  for (const GraphNode& n : graph_.nodes)
    ok = ok && n.clip < graph_clips_.size() && n.frame >= 0 && n.frame < graph_clips_[n.clip].frames;
  start_node_ = ok ? start_node : -1;
}

bool MocapMotionSource::walk(WalkCursor& c, float speed, float turn_deg_s, float dt, WalkPose& out) const {
  if (start_node_ < 0 || !std::isfinite(speed) || !std::isfinite(turn_deg_s) || !(dt > 0)) return false;
  if (c.node < 0 || c.node >= graph_.size()) {
    c.node = start_node_;
    c.frac = 0;
  }
  const float node_speed = std::max(graph_.nodes[static_cast<std::size_t>(c.node)].speed, 0.3f);
  c.frac += dt * graph_.hz * std::clamp(speed / node_speed, 0.5f, 2.0f);
  for (int guard = 0; c.frac >= 1 && guard < 8; ++guard) {
    int next = -1;
    GraphSteerJob job;
    job.graph = &graph_;
    job.node = c.node;
    job.want_speed = speed;
    job.want_turn = turn_deg_s * std::numbers::pi_v<float> / 180.0f;
    job.next = &next;
    if (!job.Run() || next < 0) return false;
    c.node = next;
    c.frac -= 1;
  }
  c.frac = std::clamp(c.frac, 0.0f, 0.999f);
  const GraphNode& n = graph_.nodes[static_cast<std::size_t>(c.node)];
  const MocapClip& clip = graph_clips_[n.clip];
  std::array<float, dof::kCount> angles{};
  float pelvis = 0, ankles[6] = {};
  MocapRetargetJob job;
  job.clip = &clip;
  job.frame = std::min(static_cast<float>(n.frame) + c.frac, static_cast<float>(clip.frames - 1));
  job.angles = angles;
  job.pelvis_height = &pelvis;
  job.ankle_targets = ankles;
  if (!job.Run()) return false;
  for (int i = 0; i < 2; ++i) {
    for (int k = 0; k < 3; ++k) out.feet[i].ankle_ms[k] = ankles[3 * i + k];
    out.feet[i].yaw_deg = 0;
    out.feet[i].pitch_deg = 0;
  }
  const float low = std::min(ankles[1], ankles[4]);
  out.planted[0] = ankles[1] < low + 0.03f;
  out.planted[1] = ankles[4] < low + 0.03f;
  out.pelvis_height = pelvis;
  out.torso_lean = angles[dof::kTorso + 1];
  out.shoulder[0] = angles[dof::kRShoulder];
  out.shoulder[1] = angles[dof::kLShoulder];
  out.elbow[0] = angles[dof::kRElbow];
  out.elbow[1] = angles[dof::kLElbow];
  for (float v : {ankles[0], ankles[1], ankles[2], ankles[3], ankles[4], ankles[5], pelvis})
    if (!std::isfinite(v)) return false;
  return true;
}

int MocapMotionSource::clip_for(const ActionMotion& m) const {
  if (kicks_.empty()) return -1;
  const auto key = static_cast<unsigned long long>(std::llround(std::max(0.0, m.contact_time_s) * 10.0));
  return static_cast<int>(key % kicks_.size());
}

bool MocapMotionSource::kick(const ActionMotion& m, float tau, float heading, float root_x, float root_y,
                             ActionSample& s) const {
  if (m.kind != MotionKind::Kick) return false;
  const int ci = clip_for(m);
  if (ci < 0 || !std::isfinite(tau)) return false;
  const Kick& k = kicks_[static_cast<std::size_t>(ci)];
  const float hz = static_cast<float>(1.0 / k.clip.frame_time);
  const float frame = std::clamp(static_cast<float>(k.contact) + tau * hz, 0.0f, static_cast<float>(k.clip.frames - 1));
  const int side = m.foot == Foot::Right ? 0 : 1;
  const float mirror = side == 0 ? 1.0f : -1.0f;  // a left kick: the right-footed clip mirrored (z -> -z)
  // The contact point in the body frame the animator poses this frame in.
  const BodyFrame body(root_x + s.root_dx, root_y + s.root_dy, heading);
  float bx = 0, bz = 0;
  body.to_body(m.contact_x, m.contact_y, bx, bz);
  std::array<float, dof::kCount> angles{};
  float pelvis = 0, ankles[6] = {};
  MocapRetargetJob job;
  job.clip = &k.clip;
  job.frame = frame;
  job.kick_foot = 0;
  job.contact_frame = static_cast<float>(k.contact);
  job.ankle_target[0] = bx;
  job.ankle_target[1] = m.contact_h;
  job.ankle_target[2] = bz * mirror;
  job.half_width = 0.3f * hz;  // the bend fades over 0.3 s, the keyframe kick's own span
  job.angles = angles;
  job.pelvis_height = &pelvis;
  job.ankle_targets = ankles;
  if (!job.Run()) return false;
  float fx = 0, fy = 0;
  body.to_field(ankles[0], ankles[2] * mirror, fx, fy);
  if (!std::isfinite(fx) || !std::isfinite(fy) || !std::isfinite(ankles[1]) || !std::isfinite(pelvis)) return false;
  s.foot_x[side] = fx;
  s.foot_y[side] = fy;
  s.foot_h[side] = std::max(ankles[1], 0.0f);
  // The plan may lower the pelvis for a lunge; the capture may crouch more.
  s.pelvis_height = std::min(s.pelvis_height, pelvis);
  const auto at = [](int d) { return static_cast<std::size_t>(d); };
  s.angles[at(dof::kTorso + 1)] = angles[at(dof::kTorso + 1)];
  const int same_sh = side == 0 ? dof::kRShoulder : dof::kLShoulder, other_sh = side == 0 ? dof::kLShoulder : dof::kRShoulder;
  const int same_el = side == 0 ? dof::kRElbow : dof::kLElbow, other_el = side == 0 ? dof::kLElbow : dof::kRElbow;
  s.angles[at(same_sh)] = angles[at(dof::kRShoulder)];
  s.angles[at(other_sh)] = angles[at(dof::kLShoulder)];
  s.angles[at(same_el)] = angles[at(dof::kRElbow)];
  s.angles[at(other_el)] = angles[at(dof::kLElbow)];
  return true;
}

}  // namespace mc::anim::mocap
