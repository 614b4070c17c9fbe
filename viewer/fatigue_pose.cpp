#include "viewer/fatigue_pose.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace mc::viewer {
namespace {

struct Target {
  const char* joint;
  char axis;
  float deg;
};
// The page's HANDS_ON_KNEES (web/src/model/fatigue.js).
constexpr Target kHandsOnKnees[] = {
    {"pelvis", 'z', -45}, {"pelvis", 'y', 0},       {"pelvis", 'x', 0},      {"torso", 'z', -15},
    {"torso", 'y', 0},    {"torso", 'x', 0},        {"neck", 'z', 25},       {"head", 'z', 12},
    {"r_upper_arm", 'z', 44}, {"r_upper_arm", 'x', 6}, {"r_upper_arm", 'y', 0},
    {"l_upper_arm", 'z', 44}, {"l_upper_arm", 'x', -6}, {"l_upper_arm", 'y', 0},
    {"r_lower_arm", 'z', 8}, {"l_lower_arm", 'z', 8},
    {"r_thigh", 'z', 80},  {"r_thigh", 'x', -5},     {"r_thigh", 'y', 0},
    {"l_thigh", 'z', 80},  {"l_thigh", 'x', 5},      {"l_thigh", 'y', 0},
    {"r_shin", 'z', -70},  {"l_shin", 'z', -70},     {"r_foot", 'z', 35},     {"r_foot", 'x', 0},
    {"l_foot", 'z', 35},   {"l_foot", 'x', 0},
};

}  // namespace

float tiredness(float stamina, float stamina_max) {
  if (!(stamina >= 0) || !(stamina_max > 0)) return 0.0f;
  return std::clamp((0.55f - stamina / stamina_max) / 0.35f, 0.0f, 1.0f);
}

float hands_on_knees_drop() {
  const double bend = 35 * 3.14159265358979323846 / 180, tilt = 45 * 3.14159265358979323846 / 180;
  return static_cast<float>(1.0 - (0.06 * std::cos(tilt) + (0.44 + 0.42) * std::cos(bend) + 0.08));
}

FatiguePose::FatiguePose(const SkeletonDef& skeleton) {
  ok_ = skeleton.name == "matchcast-human-16";
  const auto at = [&](const std::string& name, char axis) {
    int index = 0;
    for (const JointDef& j : skeleton.joints) {
      const auto k = j.dofs.find(axis);
      if (j.name == name) return k == std::string::npos ? -1 : index + static_cast<int>(k);
      index += static_cast<int>(j.dofs.size());
    }
    return -1;
  };
  torso_z_ = at("torso", 'z');
  neck_z_ = at("neck", 'z');
  arms_ = {at("r_upper_arm", 'z'), at("l_upper_arm", 'z')};
  elbows_ = {at("r_lower_arm", 'z'), at("l_lower_arm", 'z')};
  for (const Target& t : kHandsOnKnees) {
    const int i = at(t.joint, t.axis);
    if (i >= 0 && i < kMaxDof) pose_.emplace_back(i, t.deg);
  }
  ok_ = ok_ && torso_z_ >= 0 && neck_z_ >= 0;
}

void FatiguePose::apply(PoseFrame& frame, double dt, const std::array<int, kMaxPlayers>& stamina, float stamina_max) {
  if (!ok_) return;
  const bool stoppage = frame.play_mode != PlayMode::PlayOn;
  const float drop_max = hands_on_knees_drop();
  const bool timed = dt > 0 && dt < 0.5;
  for (std::size_t k = 0; k < frame.players.size(); ++k) {
    PlayerPose& p = frame.players[k];
    State& s = state_[k];
    if (!s.seen) {
      s = State{true, p.x, p.y, 0, 0};
    }
    if (timed) {
      const float v = std::hypot(p.x - s.x, p.y - s.y) / static_cast<float>(dt);
      s.speed += (v - s.speed) * std::min(1.0f, static_cast<float>(dt) / 0.3f);
    } else {
      s.speed = 0;
    }
    s.x = p.x;
    s.y = p.y;
    const float tired = tiredness(static_cast<float>(stamina[k]), stamina_max);
    auto& a = p.angles;
    if (tired > 0) {
      a[static_cast<std::size_t>(torso_z_)] -= 14 * tired;
      a[static_cast<std::size_t>(neck_z_)] += 6 * tired;
      for (int i : arms_)
        if (i >= 0) a[static_cast<std::size_t>(i)] = 5 + (a[static_cast<std::size_t>(i)] - 5) * (1 - 0.5f * tired);
      for (int i : elbows_)
        if (i >= 0) a[static_cast<std::size_t>(i)] *= 1 - 0.35f * tired;
    }
    const bool near_ball = std::hypot(p.x - frame.ball.x, p.y - frame.ball.y) < 4;
    const bool goalie = (p.state & state_bits::kGoalie) != 0;
    const float want = stoppage && tired >= 0.5f && s.speed < 0.6f && !near_ball && !goalie ? 1.0f : 0.0f;
    const float step = timed ? static_cast<float>(dt) / 0.5f : 1.0f;
    s.w = want > s.w ? std::min(want, s.w + step) : std::max(want, s.w - step);
    if (s.w <= 0) continue;
    const float w = s.w * s.w * (3 - 2 * s.w);
    for (const auto& [i, deg] : pose_) a[static_cast<std::size_t>(i)] += (deg - a[static_cast<std::size_t>(i)]) * w;
    p.z -= drop_max * w;
  }
}

}  // namespace mc::viewer
