// How pose values become integers on the wire, chosen from the error budget
// of issue 5 (largest joint-angle error 0.5 deg, largest position error 1 cm).
// SPEC.md section "Quantization" has the arithmetic; in short:
//   - rounding to a grid of step s makes the largest error s/2;
//   - joint angles: s = 0.99 deg -> error <= 0.495 deg, 0.005 deg of margin
//     below the 0.5 deg budget for float rounding (a float near 180 deg is
//     exact to 1e-5 deg); heading: 364 steps on the circle, s = 0.989 deg;
//   - positions: s = 1 cm per axis -> 0.5 cm per axis, and the 3D error is at
//     most sqrt(3) * 0.5 = 0.87 cm <= 1 cm.
// Each joint dof is coded as an index into its [min, max] limit range, so
// an unpredicted value carries at most log2(range / 0.99 + 1) bits.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "proto/pose_frame.hpp"
#include "proto/skeleton.hpp"

namespace mc::proto {

inline constexpr int kAngleStepMilliDeg = 990;     // 0.99 deg
inline constexpr double kAngleStepDeg = kAngleStepMilliDeg / 1000.0;
inline constexpr double kPositionStepM = 0.01;     // 1 cm
inline constexpr int kHeadingSteps = 364;          // 360 / 364 = 0.989 deg per step
inline constexpr double kHeadingStepDeg = 360.0 / kHeadingSteps;
inline constexpr int kPositionBits = 16;           // +-327.68 m in cm, two's complement
inline constexpr std::int32_t kPositionMin = -32768, kPositionMax = 32767;

// One dof's grid: value(q) = lo_mdeg / 1000 + q * 0.99 deg, clamped to the
// upper limit, for q in [0, steps - 1].
struct DofGrid {
  std::int32_t lo_mdeg = 0;   // lower limit, millidegrees (rounded)
  std::int32_t hi_mdeg = 0;   // upper limit, millidegrees (rounded)
  std::int32_t steps = 1;     // number of grid points, >= 1
  int bits = 0;               // keyframe field width: bits to hold steps - 1
};

// Every integer form of a frame, as both sides of the codec hold it.
struct QuantPlayer {
  std::uint8_t side = 0;      // 0 neutral, 1 left, 2 right
  std::uint8_t unum = 0;      // 0..15
  std::uint32_t state = 0;
  std::int32_t x = 0, y = 0, z = 0;  // cm
  std::int32_t heading = 0;   // [0, 364) steps of 360/364 deg from +x
  std::array<std::int32_t, kMaxDof> angles{};  // grid indices
};
struct QuantFrame {
  std::int32_t ball[3] = {0, 0, 0};  // cm
  std::array<QuantPlayer, kMaxPlayers> players{};
};

class Quantizer {
 public:
  // Dofs without limits (or with max <= min) get [-180, 180] (resp. one point).
  explicit Quantizer(const SkeletonDef& skeleton);

  int dof_count() const { return static_cast<int>(grids_.size()); }
  const DofGrid& grid(int dof) const { return grids_[static_cast<std::size_t>(dof)]; }
  // FNV-1a over dof_count and each grid's (lo, steps): a decoder refuses
  // keyframes made for a different skeleton.
  std::uint32_t fingerprint() const { return fingerprint_; }

  QuantFrame quantize(const PoseFrame& frame) const;
  // Fills positions, heading, angles, identity and state of `out` (header
  // fields are left alone). Angles past dof_count() are zeroed.
  void dequantize(const QuantFrame& q, PoseFrame& out) const;

  static std::int32_t position_q(float metres);
  static std::int32_t heading_q(float degrees);
  static float heading_value(std::int32_t q);
  std::int32_t angle_q(int dof, float degrees) const;
  float angle_value(int dof, std::int32_t q) const;

 private:
  std::vector<DofGrid> grids_;
  std::uint32_t fingerprint_ = 0;
};

}  // namespace mc::proto
