// Kovar et al.'s frame distance (the paper's equation 1): joint positions of a
// window of frames as a weighted point cloud, aligned in the floor plane
// (rotation about +Y and an x/z translation, in closed form), then the
// weighted sum of squared distances.
//
// For the motion graph the sum is evaluated from per-window sums, so one pair
// costs three dot products over the window's points: with centred x/z sums
//   C = sum w (ax bx + az bz),  S = sum w (ax bz - az bx)
// the best rotation is atan2(S, C) and the distance is
//   |a_xz|^2 + |b_xz|^2 - 2 sqrt(C^2 + S^2) + sum w (ay - by)^2.
#pragma once

#include <vector>

#include "anim/mocap/mocap_clip.hpp"

namespace mc::anim::mocap {

// Maps cloud b onto cloud a: a ~ R(theta) b + (x0, 0, z0), where
// R(theta) (x, y, z) = (x cos + z sin, y, -x sin + z cos).
struct PlanarAlign {
  float theta = 0;  // rad
  float x0 = 0, z0 = 0;
  glm::vec3 apply(const glm::vec3& p) const;
};

// Points of a cloud, structure-of-arrays; `w` holds one weight per point.
struct CloudView {
  const float* x = nullptr;
  const float* y = nullptr;
  const float* z = nullptr;
  const float* w = nullptr;
  int n = 0;
};

// The optimal planar alignment of b onto a (same point count and weights).
PlanarAlign align_planar(const CloudView& a, const CloudView& b);
// sum w |a - T b|^2 for a given alignment (the direct definition).
double cloud_distance(const CloudView& a, const CloudView& b, const PlanarAlign& t);

// The joints of a skeleton worth comparing: distinct points (a joint at its
// parent's position adds nothing) and no fingers or thumbs (not captured).
std::vector<int> cloud_joints(const MocapSkeleton& skeleton);

// Every frame's cloud, frames * points floats per axis.
struct FrameClouds {
  int frames = 0, points = 0;
  std::vector<float> x, y, z;
};
FrameClouds make_frame_clouds(const MocapClip& clip, const std::vector<int>& joints);

// Per-window sums (the part of the distance that depends on one window).
struct WindowSums {
  double w = 0, sx = 0, sz = 0, qxz = 0, qy = 0;
};

// Distance between the windows starting at point offsets `a` and `b` of
// contiguous SoA arrays (`len` points each: window frames * points) with
// per-point weights `w` (len values), given their sums. Returns the squared
// distance (>= 0); `align` (optional) receives the alignment of b onto a.
double window_distance(const float* x, const float* y, const float* z, const float* w, std::size_t a,
                       std::size_t b, int len, const WindowSums& sa, const WindowSums& sb,
                       PlanarAlign* align = nullptr);
WindowSums window_sums(const float* x, const float* y, const float* z, const float* w, std::size_t a, int len);

}  // namespace mc::anim::mocap
