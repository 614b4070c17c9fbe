// A quick float sine and cosine of an angle in degrees, for gates only.
//
// The animation's own trigonometry (portable_math.hpp, sincos_deg.hpp) is
// double precision and the same bits on every machine; what it computes
// makes the frames. A gate that only asks which side of a bound a figure
// falls on can take that figure roughly, as long as it knows how roughly:
// this one is within 3e-7 of sin and cos (anim_rough_sincos_test), and a
// caller leaves a margin far above what that moves (LegBlend::
// rough_clearance: 1 mm where it moves a foot by a micrometre).
//
// One quadrant step, then the minimax polynomials for |x| <= pi/4 of
// Moshier's Cephes sinf/cosf (the coefficients are his). No table and no
// branch on the angle: the gates that use it see a new angle every time.
#pragma once

#include <cmath>
#include <cstdint>

namespace mc::anim {

// s, c = sin, cos of `deg` degrees; NaN for |deg| >= 1e6 or NaN (callers
// then decide exactly).
inline void rough_sincos_deg(float deg, float& s, float& c) {
  if (!(std::fabs(deg) < 1e6f)) {
    s = c = NAN;
    return;
  }
  // The nearest quarter turn: deg - 90 k is exact in float (Sterbenz), so
  // the only rounding before the polynomials is the radians' one.
  const float half = deg >= 0 ? 0.5f : -0.5f;
  const auto k = static_cast<std::int32_t>(deg * (1.0f / 90.0f) + half);
  const float x = (deg - static_cast<float>(k) * 90.0f) * 0.017453292519943295f;
  const float z = x * x;
  const float sr = ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * x + x;
  const float cr = ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z -
                   0.5f * z + 1.0f;
  const std::uint32_t q = static_cast<std::uint32_t>(k) & 3u;
  const float sq = (q & 1u) != 0 ? cr : sr, cq = (q & 1u) != 0 ? sr : cr;
  s = (q & 2u) != 0 ? -sq : sq;
  c = ((q + 1u) & 2u) != 0 ? -cq : cq;
}

}  // namespace mc::anim
