#include "tests/proto/support/synthetic.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mc::proto::testing {
namespace {

JointDef joint(const char* name, int parent, std::array<float, 3> off, const char* dofs,
               std::vector<std::array<float, 2>> limits) {
  JointDef j;
  j.name = name;
  j.parent = parent;
  j.offset_ls = off;
  j.dofs = dofs;
  j.limits = std::move(limits);
  j.segment.size = {0.1f, 0.2f, 0.1f};
  return j;
}

double wrap180(double d) {
  while (d > 180) d -= 360;
  while (d <= -180) d += 360;
  return d;
}

int dof_index(const SkeletonDef& s, const char* joint_name, int axis) {
  int n = 0;
  for (const auto& j : s.joints) {
    if (j.name == joint_name) return n + axis;
    n += static_cast<int>(j.dofs.size());
  }
  return -1;
}

}  // namespace

SkeletonDef humanoid_skeleton() {
  SkeletonDef s;
  s.name = "test-humanoid-36";
  const std::vector<std::array<float, 2>> l3 = {{-45, 45}, {-45, 45}, {-30, 30}};
  s.joints.push_back(joint("pelvis", -1, {0, 0, 0}, "zxy", l3));                       // 0
  s.joints.push_back(joint("spine", 0, {0, 0.1f, 0}, "zxy", l3));                      // 1
  s.joints.push_back(joint("chest", 1, {0, 0.2f, 0}, "zxy", l3));                      // 2
  s.joints.push_back(joint("neck", 2, {0, 0.2f, 0}, "zxy", {{-40, 60}, {-40, 40}, {-80, 80}}));  // 3
  s.joints.push_back(joint("head", 3, {0, 0.1f, 0}, "zy", {{-40, 40}, {-30, 30}}));    // 4
  for (int side = 0; side < 2; ++side) {
    const float z = side == 0 ? -0.18f : 0.18f;
    const int base = static_cast<int>(s.joints.size());
    s.joints.push_back(joint(side == 0 ? "l_shoulder" : "r_shoulder", 2, {0, 0.15f, z}, "zxy",
                             {{-90, 180}, {-30, 150}, {-90, 90}}));
    s.joints.push_back(joint(side == 0 ? "l_elbow" : "r_elbow", base, {0, -0.3f, 0}, "z", {{0, 150}}));
    s.joints.push_back(joint(side == 0 ? "l_wrist" : "r_wrist", base + 1, {0, -0.25f, 0}, "z", {{-70, 70}}));
  }
  for (int side = 0; side < 2; ++side) {
    const float z = side == 0 ? -0.1f : 0.1f;
    const int base = static_cast<int>(s.joints.size());
    s.joints.push_back(joint(side == 0 ? "l_hip" : "r_hip", 0, {0, -0.05f, z}, "zxy",
                             {{-30, 120}, {-45, 30}, {-45, 45}}));
    s.joints.push_back(joint(side == 0 ? "l_knee" : "r_knee", base, {0, -0.45f, 0}, "z", {{-150, 0}}));
    s.joints.push_back(joint(side == 0 ? "l_ankle" : "r_ankle", base + 1, {0, -0.45f, 0}, "zx",
                             {{-50, 30}, {-25, 25}}));
  }
  return s;
}

GaitSynth::GaitSynth(const SkeletonDef& skeleton) : skeleton_(skeleton) {}

void GaitSynth::pose_player(const PlayerState& a, const PlayerState& b, double t, int slot,
                            const BallState& ball, PlayerPose& out) {
  const SkeletonDef& s = skeleton_;
  out.side = a.side;
  out.unum = a.unum;
  out.state = a.state;
  const double x = a.x + (b.x - a.x) * t, y = a.y + (b.y - a.y) * t;
  const double speed = std::hypot(b.x - a.x, b.y - a.y) / 0.1;  // m/s
  out.x = static_cast<float>(x);
  out.y = static_cast<float>(y);
  out.heading = static_cast<float>(wrap180(a.body + wrap180(b.body - a.body) * t));
  out.angles.fill(0.0f);
  if (!a.active()) {
    out.z = 0.95f;  // parked, rest pose
    return;
  }
  // Stride length grows with speed; the phase advances with distance run.
  const double stride = 0.9 + 0.5 * std::min(speed / 6.0, 1.0);
  double& phase = phase_[slot];
  phase += std::numbers::pi * (speed * 0.05) / stride;
  const double amp = std::min(speed / 6.0, 1.0);
  const double sp = std::sin(phase), cp = std::cos(phase);
  const auto set = [&](const char* j, int axis, double v) {
    const int d = dof_index(s, j, axis);
    if (d >= 0) out.angles[static_cast<std::size_t>(d)] = static_cast<float>(v);
  };
  out.z = static_cast<float>(0.95 - 0.04 * amp + 0.03 * amp * std::abs(cp));
  // Standing players breathe and sway slightly, as an idle clip would.
  const double idle = std::sin(seq_ * 0.1 + slot);
  set("pelvis", 0, -8 * amp);
  set("pelvis", 2, 8 * amp * sp);
  set("spine", 0, 5 * amp + 1.5 * idle * (1 - amp));
  set("spine", 2, -6 * amp * sp);
  set("chest", 0, 2 * amp + 1.0 * idle * (1 - amp));
  set("chest", 1, 2 * amp * cp);
  // Head looks at the ball, limited by the neck range.
  const double to_ball = std::atan2(ball.y - y, ball.x - x) * 180 / std::numbers::pi;
  set("neck", 2, std::clamp(-wrap180(to_ball - out.heading), -80.0, 80.0));
  set("neck", 0, -10.0);
  set("head", 0, -5 + 3 * amp * sp);
  for (int side = 0; side < 2; ++side) {
    const double ph = side == 0 ? sp : -sp;
    const double pc = side == 0 ? cp : -cp;
    set(side ? "r_shoulder" : "l_shoulder", 0, -40 * amp * ph + 2 * idle);
    set(side ? "r_shoulder" : "l_shoulder", 1, 8 + 4 * amp);
    set(side ? "r_elbow" : "l_elbow", 0, 20 + 60 * amp + 10 * amp * pc);
    set(side ? "r_wrist" : "l_wrist", 0, 5);
    set(side ? "r_hip" : "l_hip", 0, 10 * amp + 40 * amp * ph);
    set(side ? "r_hip" : "l_hip", 1, -3 * amp * pc);
    set(side ? "r_knee" : "l_knee", 0, -5 - 70 * amp * std::max(0.0, -pc) - 15 * amp);
    set(side ? "r_ankle" : "l_ankle", 0, 10 * amp * ph - 5 * amp);
  }
}

void GaitSynth::add(const WorldState& state, const WorldState& next, std::vector<PoseFrame>& out) {
  for (int sub = 0; sub < kFramesPerCycle; ++sub) {
    PoseFrame f;
    f.seq = seq_++;
    f.time = state.time;
    f.stoppage = state.stoppage;
    f.substep = static_cast<std::uint8_t>(sub);
    f.server_time_ms = 1'700'000'000'000ull + f.seq * kFrameIntervalMs;
    f.play_mode = state.play_mode;
    f.score_left = static_cast<std::uint8_t>(state.left.score);
    f.score_right = static_cast<std::uint8_t>(state.right.score);
    const double t = sub * 0.5;
    f.ball.x = static_cast<float>(state.ball.x + (next.ball.x - state.ball.x) * t);
    f.ball.y = static_cast<float>(state.ball.y + (next.ball.y - state.ball.y) * t);
    const double v = std::hypot(state.ball.vx, state.ball.vy);
    f.ball.z = static_cast<float>(0.085 + (v > 2.0 ? (v - 2.0) * 1.5 : 0.0));
    for (int i = 0; i < kMaxPlayers; ++i)
      pose_player(state.players[static_cast<std::size_t>(i)], next.players[static_cast<std::size_t>(i)], t, i,
                  state.ball, f.players[static_cast<std::size_t>(i)]);
    out.push_back(f);
  }
}

std::vector<PoseFrame> scripted_frames(const SkeletonDef& skeleton, int count, unsigned seed) {
  // A tiny deterministic game: states at 10 Hz, turned into frames by the synth.
  GaitSynth synth(skeleton);
  const auto state_at = [&](int c) {
    WorldState w;
    w.index = static_cast<std::uint64_t>(c);
    w.time = c;
    w.play_mode = PlayMode::PlayOn;
    w.left.score = c > 40 ? 1 : 0;
    w.ball.x = 10.0 * std::sin(c * 0.05 + seed);
    w.ball.y = 5.0 * std::cos(c * 0.07);
    w.ball.vx = std::cos(c * 0.05 + seed) * 0.5;
    w.ball.vy = 0.3;
    for (int i = 0; i < kMaxPlayers; ++i) {
      PlayerState& p = w.players[static_cast<std::size_t>(i)];
      p.side = i < kPlayersPerSide ? Side::Left : Side::Right;
      p.unum = static_cast<std::uint8_t>(i % kPlayersPerSide + 1);
      p.state = (i == 10 || i == 21) ? 0u : state_bits::kStand | (i % 11 == 0 ? state_bits::kGoalie : 0u);
      const double r = 3.0 + i % 5;
      const double w0 = (i % 3 == 0) ? 0.0 : 0.04 + 0.01 * (i % 4);  // every third stands still
      p.x = (p.side == Side::Left ? -20.0 : 20.0) + r * std::cos(c * w0 + i);
      p.y = -30.0 + 3.0 * (i % 11) + r * std::sin(c * w0 + i);
      if (p.state == 0) p.y = -37.0, p.x = -3.0 * (i % 11);
      p.body = std::atan2(std::cos(c * w0 + i), -std::sin(c * w0 + i)) * 180 / std::numbers::pi;
    }
    return w;
  };
  std::vector<PoseFrame> out;
  for (int c = 0; static_cast<int>(out.size()) < count; ++c) synth.add(state_at(c), state_at(c + 1), out);
  out.resize(static_cast<std::size_t>(count));
  return out;
}

}  // namespace mc::proto::testing
