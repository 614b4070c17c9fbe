#include "anim/mocap/frame_distance.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace mc::anim::mocap {

glm::vec3 PlanarAlign::apply(const glm::vec3& p) const {
  const float c = std::cos(theta), s = std::sin(theta);
  return {p.x * c + p.z * s + x0, p.y, -p.x * s + p.z * c + z0};
}

PlanarAlign align_planar(const CloudView& a, const CloudView& b) {
  double w = 0, ax = 0, az = 0, bx = 0, bz = 0, c = 0, s = 0;
  for (int i = 0; i < a.n; ++i) {
    const double wi = a.w[i];
    w += wi;
    ax += wi * a.x[i]; az += wi * a.z[i];
    bx += wi * b.x[i]; bz += wi * b.z[i];
    c += wi * (a.x[i] * b.x[i] + a.z[i] * b.z[i]);
    s += wi * (a.x[i] * b.z[i] - a.z[i] * b.x[i]);
  }
  PlanarAlign t;
  if (w <= 0) return t;
  c -= (ax * bx + az * bz) / w;
  s -= (ax * bz - az * bx) / w;
  const double th = (c == 0 && s == 0) ? 0.0 : std::atan2(s, c);
  const double ct = std::cos(th), st = std::sin(th);
  t.theta = static_cast<float>(th);
  // t = mean(a) - R mean(b)
  t.x0 = static_cast<float>((ax - (bx * ct + bz * st)) / w);
  t.z0 = static_cast<float>((az - (-bx * st + bz * ct)) / w);
  return t;
}

double cloud_distance(const CloudView& a, const CloudView& b, const PlanarAlign& t) {
  double d = 0;
  for (int i = 0; i < a.n; ++i) {
    const glm::vec3 q = t.apply({b.x[i], b.y[i], b.z[i]});
    const double dx = a.x[i] - q.x, dy = a.y[i] - q.y, dz = a.z[i] - q.z;
    d += a.w[i] * (dx * dx + dy * dy + dz * dz);
  }
  return d;
}

std::vector<int> cloud_joints(const MocapSkeleton& s) {
  std::vector<int> out;
  std::vector<bool> hand_descendant(s.names.size(), false);
  for (std::size_t j = 0; j < s.names.size(); ++j) {
    const int p = s.parents[j];
    const auto& parent_name = p >= 0 ? s.names[static_cast<std::size_t>(p)] : std::string();
    hand_descendant[j] = p >= 0 && (hand_descendant[static_cast<std::size_t>(p)] || parent_name == "LeftHand" ||
                                    parent_name == "RightHand");
    if (hand_descendant[j]) continue;
    if (p >= 0 && glm::length(s.offsets[j]) < 1e-3f) continue;  // same point as the parent
    out.push_back(static_cast<int>(j));
  }
  return out;
}

FrameClouds make_frame_clouds(const MocapClip& clip, const std::vector<int>& joints) {
  FrameClouds c;
  c.frames = clip.frames;
  c.points = static_cast<int>(joints.size());
  const std::size_t total = static_cast<std::size_t>(c.frames) * joints.size();
  c.x.resize(total); c.y.resize(total); c.z.resize(total);
  std::vector<glm::vec3> p;
  for (int f = 0; f < clip.frames; ++f) {
    forward_kinematics(clip, f, p);
    for (std::size_t k = 0; k < joints.size(); ++k) {
      const auto i = static_cast<std::size_t>(f) * joints.size() + k;
      const auto& q = p[static_cast<std::size_t>(joints[k])];
      c.x[i] = q.x; c.y[i] = q.y; c.z[i] = q.z;
    }
  }
  return c;
}

WindowSums window_sums(const float* x, const float* y, const float* z, const float* w, std::size_t a, int len) {
  WindowSums s;
  for (int i = 0; i < len; ++i) {
    const double wi = w[i], px = x[a + static_cast<std::size_t>(i)], py = y[a + static_cast<std::size_t>(i)],
                 pz = z[a + static_cast<std::size_t>(i)];
    s.w += wi; s.sx += wi * px; s.sz += wi * pz;
    s.qxz += wi * (px * px + pz * pz);
    s.qy += wi * py * py;
  }
  return s;
}

double window_distance(const float* x, const float* y, const float* z, const float* w, std::size_t a,
                       std::size_t b, int len, const WindowSums& sa, const WindowSums& sb, PlanarAlign* align) {
  // Three weighted dot products; float accumulation in the loop (vectorizes),
  // the window is short (hundreds of points).
  const float* ax = x + a; const float* ay = y + a; const float* az = z + a;
  const float* bx = x + b; const float* by = y + b; const float* bz = z + b;
  float c = 0, s = 0, yy = 0;
  for (int i = 0; i < len; ++i) {
    c += w[i] * (ax[i] * bx[i] + az[i] * bz[i]);
    s += w[i] * (ax[i] * bz[i] - az[i] * bx[i]);
    yy += w[i] * ay[i] * by[i];
  }
  const double W = sa.w;
  if (W <= 0) return 0;
  const double cc = c - (sa.sx * sb.sx + sa.sz * sb.sz) / W;
  const double ss = s - (sa.sx * sb.sz - sa.sz * sb.sx) / W;
  const double qa = sa.qxz - (sa.sx * sa.sx + sa.sz * sa.sz) / W;
  const double qb = sb.qxz - (sb.sx * sb.sx + sb.sz * sb.sz) / W;
  const double d = qa + qb - 2 * std::sqrt(cc * cc + ss * ss) + sa.qy + sb.qy - 2 * yy;
  if (align) {
    const double th = (cc == 0 && ss == 0) ? 0.0 : std::atan2(ss, cc);
    const double ct = std::cos(th), st = std::sin(th);
    align->theta = static_cast<float>(th);
    align->x0 = static_cast<float>((sa.sx - (sb.sx * ct + sb.sz * st)) / W);
    align->z0 = static_cast<float>((sa.sz - (-sb.sx * st + sb.sz * ct)) / W);
  }
  return std::max(0.0, d);
}

}  // namespace mc::anim::mocap
