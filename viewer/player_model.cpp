#include "viewer/player_model.hpp"

#include <algorithm>
#include <cctype>
#include <span>

#include <glm/gtc/matrix_transform.hpp>

#include "anim/local_to_model_job.hpp"

namespace mc::viewer {
namespace {

constexpr float kDeg = 3.14159265358979f / 180.0f;

bool has(const std::string& s, std::initializer_list<const char*> words) {
  return std::any_of(words.begin(), words.end(), [&](const char* w) { return s.find(w) != std::string::npos; });
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

}  // namespace

Part part_of(std::string_view joint_name) {
  std::string n(joint_name);
  for (auto& c : n) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (has(n, {"head", "neck", "skull", "hand", "wrist", "finger", "elbow", "fore", "lower_arm", "lowerarm"}))
    return Part::Skin;
  if (has(n, {"toe", "foot", "ankle"})) return Part::Boot;
  if (has(n, {"knee", "shin", "calf", "lower_leg", "lowerleg"})) return Part::Sock;
  if (has(n, {"hip", "thigh", "upper_leg", "upleg", "pelvis", "root"})) return Part::Shorts;
  return Part::Shirt;
}

glm::vec3 parse_color(std::string_view text, glm::vec3 fallback) {
  if (!text.empty() && text[0] == '#') text.remove_prefix(1);
  if (text.size() != 6 && text.size() != 3) return fallback;
  int v[6];
  for (std::size_t i = 0; i < text.size(); ++i)
    if ((v[i] = hex_digit(text[i])) < 0) return fallback;
  if (text.size() == 3) return {v[0] / 15.0f, v[1] / 15.0f, v[2] / 15.0f};
  return {(v[0] * 16 + v[1]) / 255.0f, (v[2] * 16 + v[3]) / 255.0f, (v[4] * 16 + v[5]) / 255.0f};
}

glm::vec3 Kit::color(Part part) const {
  switch (part) {
    case Part::Shirt: return shirt;
    case Part::Shorts: return shorts;
    case Part::Skin: return skin;
    case Part::Sock: return sock;
    case Part::Boot: return boot;
  }
  return shirt;
}

Kit team_kit(const proto::TeamHello& team, Side side, bool goalie) {
  // The page's defaults (web/src/scene/kit.js DEFAULT_TEAMS).
  const bool left = side != Side::Right;
  const glm::vec3 shirt = parse_color(team.color, left ? glm::vec3(0.95f, 0.77f, 0.0f) : glm::vec3(0.84f, 0.16f, 0.16f));
  const glm::vec3 keeper = left ? parse_color("#7d3cb5", {}) : parse_color("#16a6b6", {});
  Kit kit;
  kit.skin = parse_color("#c99a74", {});
  kit.boot = glm::vec3(0.09f);
  kit.shirt = goalie ? keeper : shirt;
  kit.sock = kit.shirt;
  kit.shorts = kit.shirt * (goalie ? 0.4f : 0.35f);
  // Readable numbers: dark on light shirts, white on dark ones.
  const float l = 0.2126f * kit.shirt.r + 0.7152f * kit.shirt.g + 0.0722f * kit.shirt.b;
  kit.number = l > 0.45f ? glm::vec3(0.07f) : glm::vec3(1.0f);
  return kit;
}

PlayerModel::PlayerModel(const SkeletonDef& skeleton) : skeleton_(skeleton) {
  float best = 0;
  for (std::size_t i = 0; i < skeleton_.joints.size(); ++i) {
    const auto& j = skeleton_.joints[i];
    parts_.push_back(part_of(j.name));
    std::string n = j.name;
    for (auto& c : n) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (head_ < 0 && n.find("head") != std::string::npos) head_ = static_cast<int>(i);
    const auto& s = j.segment.size;
    if (parts_.back() == Part::Shirt && j.segment.shape == SegmentShape::Box && s[0] * s[1] * s[2] > best) {
      best = s[0] * s[1] * s[2];
      chest_ = static_cast<int>(i);
    }
  }
  if (head_ < 0) head_ = static_cast<int>(skeleton_.joints.size()) - 1;
}

bool PlayerModel::joints(const PlayerPose& pose, std::vector<glm::mat4>& out) const {
  out.resize(skeleton_.joints.size());
  if (out.empty()) return false;
  anim::LocalToModelJob job;
  job.skeleton = &skeleton_;
  job.angles_deg = std::span<const float>(pose.angles.data(), pose.angles.size());
  job.root_ms = glm::vec3(0.0f, pose.z, 0.0f);
  job.models = out;
  if (!job.Run()) return false;
  glm::mat4 place = glm::translate(glm::mat4(1.0f), glm::vec3(pose.x, 0.0f, pose.y));
  place = glm::rotate(place, -pose.heading * kDeg, glm::vec3(0.0f, 1.0f, 0.0f));
  for (auto& m : out) m = place * m;
  return true;
}

void PlayerModel::segments(const std::vector<glm::mat4>& joints, std::vector<SegmentInstance>& out) const {
  out.clear();
  for (std::size_t i = 0; i < skeleton_.joints.size() && i < joints.size(); ++i) {
    const Segment& s = skeleton_.joints[i].segment;
    const glm::vec3 center(s.center[0], s.center[1], s.center[2]);
    SegmentInstance inst;
    inst.part = parts_[i];
    if (s.shape == SegmentShape::Sphere) {
      if (s.size[0] <= 0) continue;
      inst.sphere = true;
      inst.model = glm::scale(glm::translate(joints[i], center), glm::vec3(s.size[0]));
    } else {
      if (s.size[0] <= 0 || s.size[1] <= 0 || s.size[2] <= 0) continue;
      inst.model = glm::scale(glm::translate(joints[i], center), glm::vec3(s.size[0], s.size[1], s.size[2]));
    }
    out.push_back(inst);
  }
}

glm::vec3 PlayerModel::segment_center(const std::vector<glm::mat4>& joints, int joint) const {
  if (joint < 0 || joint >= static_cast<int>(joints.size())) return glm::vec3(0.0f);
  const auto& c = skeleton_.joints[static_cast<std::size_t>(joint)].segment.center;
  return glm::vec3(joints[static_cast<std::size_t>(joint)] * glm::vec4(c[0], c[1], c[2], 1.0f));
}

}  // namespace mc::viewer
