#include "anim/mocap/mocap_clip.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace mc::anim::mocap {

int MocapSkeleton::find(const std::string& name) const {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int>(i);
  return -1;
}

void forward_kinematics(const MocapClip& clip, int frame, std::vector<glm::vec3>& out) {
  const auto& s = clip.skeleton;
  const std::size_t n = s.names.size();
  out.resize(n);
  // Model-space rotations.
  std::vector<glm::quat> rot(n);
  const glm::quat* local = clip.pose(frame);
  for (std::size_t j = 0; j < n; ++j) {
    const int p = s.parents[j];
    if (p < 0) {
      rot[j] = local[j];
      out[j] = clip.root_position[static_cast<std::size_t>(frame)];
    } else {
      const auto pj = static_cast<std::size_t>(p);
      rot[j] = rot[pj] * local[j];
      out[j] = out[pj] + rot[pj] * s.offsets[j];
    }
  }
}

bool looks_like_cgspeed_tpose(const std::vector<double>& deg) {
  if (deg.size() < 3) return false;
  for (int i = 0; i < 3; ++i)
    if (deg[static_cast<std::size_t>(i)] != 0) return false;
  bool any = false;
  for (double d : deg) {
    if (d != std::round(d) || std::fabs(d) > 30) return false;
    any = any || d != 0;
  }
  return any;
}

void drop_frames(MocapClip& clip, int count) {
  count = std::clamp(count, 0, clip.frames);
  const auto nj = clip.skeleton.names.size();
  clip.root_position.erase(clip.root_position.begin(), clip.root_position.begin() + count);
  clip.local.erase(clip.local.begin(), clip.local.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(count) * nj));
  clip.frames -= count;
}

MocapClip resample(const MocapClip& clip, double hz) {
  MocapClip out;
  out.name = clip.name;
  out.skeleton = clip.skeleton;
  out.frame_time = 1.0 / hz;
  if (clip.frames <= 0 || !(hz > 0)) return out;
  const double duration = (clip.frames - 1) * clip.frame_time;
  const int n = static_cast<int>(std::floor(duration * hz + 1e-9)) + 1;
  const auto nj = clip.skeleton.names.size();
  out.frames = n;
  out.root_position.resize(static_cast<std::size_t>(n));
  out.local.resize(static_cast<std::size_t>(n) * nj);
  for (int k = 0; k < n; ++k) {
    const double src = k / hz / clip.frame_time;
    const int a = std::min(static_cast<int>(std::floor(src)), clip.frames - 1);
    const int b = std::min(a + 1, clip.frames - 1);
    const float t = static_cast<float>(src - a);
    const auto ka = static_cast<std::size_t>(k);
    out.root_position[ka] = glm::mix(clip.root_position[static_cast<std::size_t>(a)], clip.root_position[static_cast<std::size_t>(b)], t);
    const glm::quat* pa = clip.pose(a);
    const glm::quat* pb = clip.pose(b);
    glm::quat* po = out.pose(k);
    for (std::size_t j = 0; j < nj; ++j) po[j] = glm::slerp(pa[j], pb[j], t);
  }
  return out;
}

namespace {
// Rest length of the chain from the root to the named joint (m), 0 if absent.
float chain_length(const MocapSkeleton& s, int j) {
  float len = 0;
  for (; j > 0; j = s.parents[static_cast<std::size_t>(j)]) len += glm::length(s.offsets[static_cast<std::size_t>(j)]);
  return len;
}
float leg_length(const MocapSkeleton& s) {
  for (const char* foot : {"LeftFoot", "RightFoot"}) {
    const int j = s.find(foot);
    if (j > 0) return chain_length(s, j);
  }
  return 0;
}
}  // namespace

int retarget_offsets(MocapClip& clip, const MocapSkeleton& canonical) {
  const float before = leg_length(clip.skeleton);
  int matched = 0;
  for (std::size_t j = 0; j < clip.skeleton.names.size(); ++j) {
    const int c = canonical.find(clip.skeleton.names[j]);
    if (c < 0) continue;
    clip.skeleton.offsets[j] = canonical.offsets[static_cast<std::size_t>(c)];
    ++matched;
  }
  const float after = leg_length(clip.skeleton);
  if (before > 0 && after > 0) {
    const float k = after / before;
    for (auto& p : clip.root_position) p *= k;
  }
  return matched;
}

glm::vec2 facing_xz(const std::vector<glm::vec3>& p, int left_hip, int right_hip) {
  const glm::vec3 lr = p[static_cast<std::size_t>(left_hip)] - p[static_cast<std::size_t>(right_hip)];
  // facing = (L - R) x up, horizontal: (lr.x, lr.z) rotated.
  glm::vec2 f(-lr.z, lr.x);
  const float len = glm::length(f);
  return len > 1e-6f ? f / len : glm::vec2(0, 1);
}

}  // namespace mc::anim::mocap
