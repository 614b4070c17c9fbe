#include "proto/quantizer.hpp"

#include <algorithm>
#include <cmath>

namespace mc::proto {
namespace {

int bits_for(std::int32_t max_value) {
  int bits = 0;
  while (bits < 31 && (static_cast<std::int64_t>(1) << bits) <= max_value) ++bits;
  return bits;
}

void fnv(std::uint32_t& h, std::int32_t v) {
  const auto u = static_cast<std::uint32_t>(v);
  for (int i = 0; i < 4; ++i) {
    h ^= (u >> (8 * i)) & 0xffu;
    h *= 16777619u;
  }
}

std::uint8_t side_code(Side s) { return s == Side::Left ? 1 : s == Side::Right ? 2 : 0; }
Side side_value(std::uint8_t c) { return c == 1 ? Side::Left : c == 2 ? Side::Right : Side::Neutral; }

}  // namespace

Quantizer::Quantizer(const SkeletonDef& skeleton) {
  grids_.reserve(kMaxDof);
  for (const auto& joint : skeleton.joints) {
    for (std::size_t d = 0; d < joint.dofs.size(); ++d) {
      if (static_cast<int>(grids_.size()) >= kMaxDof) break;
      double lo = -180, hi = 180;
      if (d < joint.limits.size()) lo = joint.limits[d][0], hi = joint.limits[d][1];
      DofGrid g;
      g.lo_mdeg = static_cast<std::int32_t>(std::lround(lo * 1000.0));
      g.hi_mdeg = std::max(g.lo_mdeg, static_cast<std::int32_t>(std::lround(hi * 1000.0)));
      // Integer ceil so that the JavaScript side computes the same count.
      const std::int32_t range = g.hi_mdeg - g.lo_mdeg;
      g.steps = (range + kAngleStepMilliDeg - 1) / kAngleStepMilliDeg + 1;
      g.bits = bits_for(g.steps - 1);
      grids_.push_back(g);
    }
  }
  fingerprint_ = 2166136261u;
  fnv(fingerprint_, dof_count());
  for (const auto& g : grids_) {
    fnv(fingerprint_, g.lo_mdeg);
    fnv(fingerprint_, g.steps);
  }
}

std::int32_t Quantizer::position_q(float metres) {
  if (!std::isfinite(metres)) return 0;
  const double q = std::round(static_cast<double>(metres) / kPositionStepM);
  return static_cast<std::int32_t>(std::clamp(q, double{kPositionMin}, double{kPositionMax}));
}

std::int32_t Quantizer::heading_q(float degrees) {
  if (!std::isfinite(degrees)) return 0;
  const double steps = std::round(static_cast<double>(degrees) / kHeadingStepDeg);
  double m = std::fmod(steps, kHeadingSteps);
  if (m < 0) m += kHeadingSteps;
  return static_cast<std::int32_t>(m) % kHeadingSteps;
}

float Quantizer::heading_value(std::int32_t q) {
  // (-180, 180], matching PlayerState::body's convention.
  double deg = q * kHeadingStepDeg;
  if (deg > 180.0) deg -= 360.0;
  return static_cast<float>(deg);
}

std::int32_t Quantizer::angle_q(int dof, float degrees) const {
  const DofGrid& g = grid(dof);
  if (!std::isfinite(degrees)) return 0;
  const double q = std::round((static_cast<double>(degrees) * 1000.0 - g.lo_mdeg) / kAngleStepMilliDeg);
  return static_cast<std::int32_t>(std::clamp(q, 0.0, static_cast<double>(g.steps - 1)));
}

float Quantizer::angle_value(int dof, std::int32_t q) const {
  const DofGrid& g = grid(dof);
  const std::int64_t mdeg = std::min<std::int64_t>(g.lo_mdeg + static_cast<std::int64_t>(q) * kAngleStepMilliDeg, g.hi_mdeg);
  return static_cast<float>(static_cast<double>(mdeg) / 1000.0);
}

QuantFrame Quantizer::quantize(const PoseFrame& frame) const {
  QuantFrame q;
  q.ball[0] = position_q(frame.ball.x);
  q.ball[1] = position_q(frame.ball.y);
  q.ball[2] = position_q(frame.ball.z);
  for (int i = 0; i < kMaxPlayers; ++i) {
    const PlayerPose& p = frame.players[static_cast<std::size_t>(i)];
    QuantPlayer& o = q.players[static_cast<std::size_t>(i)];
    o.side = side_code(p.side);
    o.unum = static_cast<std::uint8_t>(p.unum & 0x0fu);
    o.state = p.state & 0x7fffffffu;
    o.x = position_q(p.x);
    o.y = position_q(p.y);
    o.z = position_q(p.z);
    o.heading = heading_q(p.heading);
    for (int d = 0; d < dof_count(); ++d) o.angles[static_cast<std::size_t>(d)] = angle_q(d, p.angles[static_cast<std::size_t>(d)]);
  }
  return q;
}

void Quantizer::dequantize(const QuantFrame& q, PoseFrame& out) const {
  out.ball.x = static_cast<float>(q.ball[0] * kPositionStepM);
  out.ball.y = static_cast<float>(q.ball[1] * kPositionStepM);
  out.ball.z = static_cast<float>(q.ball[2] * kPositionStepM);
  for (int i = 0; i < kMaxPlayers; ++i) {
    const QuantPlayer& p = q.players[static_cast<std::size_t>(i)];
    PlayerPose& o = out.players[static_cast<std::size_t>(i)];
    o.side = side_value(p.side);
    o.unum = p.unum;
    o.state = p.state;
    o.x = static_cast<float>(p.x * kPositionStepM);
    o.y = static_cast<float>(p.y * kPositionStepM);
    o.z = static_cast<float>(p.z * kPositionStepM);
    o.heading = heading_value(p.heading);
    o.angles.fill(0.0f);
    for (int d = 0; d < dof_count(); ++d) o.angles[static_cast<std::size_t>(d)] = angle_value(d, p.angles[static_cast<std::size_t>(d)]);
  }
}

}  // namespace mc::proto
