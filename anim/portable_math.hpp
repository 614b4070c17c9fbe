// The trigonometry of the animation, the same bits on every machine and
// build. The C library's sinf, atan2f, acosf... are not: glibc picks an FMA
// variant at run time on CPUs that have FMA, and emscripten's musl (the
// page's WebAssembly module) has its own implementations, each within an
// ulp or so of the others. An ulp is enough to move a joint angle across a
// quantization step now and then, and the animator promises equal output
// for equal input: the server and the page must make the same frames.
//
// So these are written with + - * / and sqrt only (all correctly rounded by
// IEEE 754, with no fused multiply-add: GCC in ISO C++ mode does not
// contract, and WebAssembly has no FMA), in double precision: fdlibm's
// argument reduction and polynomials (Sun Microsystems, "Permission to use,
// copy, modify, and distribute this software is freely granted, provided
// that this notice is preserved"). Double results are within about 1 ulp;
// float results are the double result rounded, so almost always the
// correctly rounded float.
#pragma once

#include <cmath>

namespace mc::anim::pm {

namespace detail {

// sin and cos of r, |r| <= pi/4 (fdlibm __kernel_sin, __kernel_cos).
inline double kernel_sin(double r) {
  const double z = r * r;
  const double p = -1.66666666666666324348e-01 +
                   z * (8.33333333332248946124e-03 +
                        z * (-1.98412698298579493134e-04 +
                             z * (2.75573137070700676789e-06 +
                                  z * (-2.50507602534068634195e-08 + z * 1.58969099521155010221e-10))));
  return r + r * z * p;
}

inline double kernel_cos(double r) {
  const double z = r * r;
  const double p = 4.16666666666666019037e-02 +
                   z * (-1.38888888888741095749e-03 +
                        z * (2.48015872894767294178e-05 +
                             z * (-2.75573143513906633035e-07 +
                                  z * (2.08757232129817482790e-09 + z * -1.13596475577881948265e-11))));
  const double hz = 0.5 * z;
  const double w = 1.0 - hz;
  return w + (((1.0 - w) - hz) + z * z * p);
}

// x = k pi/2 + r with |r| <= ~pi/4; the quadrant k mod 4 (Cody-Waite in
// three parts, exact products for |k| < 2^20; farther out, first wrapped
// into one turn, which no animation angle needs).
inline double reduce(double x, int& quadrant) {
  constexpr double kTwoPi = 6.28318530717958647692;
  if (!(std::fabs(x) < 1e6)) x = std::fmod(x, kTwoPi);
  const double k = std::floor(x * 6.36619772367581382433e-01 + 0.5);  // x * 2/pi, nearest
  const double r = ((x - k * 1.57079632673412561417e+00) - k * 6.07710050630396597660e-11) -
                   k * 2.02226624871116645580e-21;
  quadrant = static_cast<int>(static_cast<long long>(k) & 3);
  return r;
}

// atan(x) for x >= 0 (fdlibm s_atan.c).
inline double atan_pos(double x) {
  static constexpr double kHi[] = {4.63647609000806093515e-01, 7.85398163397448278999e-01,
                                   9.82793723247329054082e-01, 1.57079632679489655800e+00};
  static constexpr double kLo[] = {2.26987774529616870924e-17, 3.06161699786838301793e-17,
                                   1.39033110312309984516e-17, 6.12323399573676603587e-17};
  int id = -1;
  if (x >= 2.4375) {
    if (x > 1e17) return kHi[3] + kLo[3];
    id = 3;
    x = -1.0 / x;
  } else if (x >= 1.1875) {
    id = 2;
    x = (x - 1.5) / (1.0 + 1.5 * x);
  } else if (x >= 0.6875) {
    id = 1;
    x = (x - 1.0) / (x + 1.0);
  } else if (x >= 0.4375) {
    id = 0;
    x = (2.0 * x - 1.0) / (2.0 + x);
  } else if (x < 1e-9) {
    return x;
  }
  const double z = x * x;
  const double w = z * z;
  const double s1 = z * (3.33333333333329318027e-01 +
                         w * (1.42857142725034663711e-01 +
                              w * (9.09088713343650656196e-02 +
                                   w * (6.66107313738753120669e-02 +
                                        w * (4.97687799461593236017e-02 + w * 1.62858201153657823623e-02)))));
  const double s2 = w * (-1.99999999998764832476e-01 +
                         w * (-1.11111104054623557880e-01 +
                              w * (-7.69187620504482999495e-02 +
                                   w * (-5.83357013379057348645e-02 + w * -3.65315727442169155270e-02))));
  if (id < 0) return x - x * (s1 + s2);
  return kHi[id] - ((x * (s1 + s2) - kLo[id]) - x);
}

}  // namespace detail

inline double sin(double x) {
  if (!std::isfinite(x)) return x - x;  // NaN
  if (x == 0) return x;                 // keeps the sign of zero
  int q = 0;
  const double r = detail::reduce(x, q);
  switch (q) {
    case 0: return detail::kernel_sin(r);
    case 1: return detail::kernel_cos(r);
    case 2: return -detail::kernel_sin(r);
    default: return -detail::kernel_cos(r);
  }
}

inline double cos(double x) {
  if (!std::isfinite(x)) return x - x;
  int q = 0;
  const double r = detail::reduce(x, q);
  switch (q) {
    case 0: return detail::kernel_cos(r);
    case 1: return -detail::kernel_sin(r);
    case 2: return -detail::kernel_cos(r);
    default: return detail::kernel_sin(r);
  }
}

// sin(x) and cos(x), bit for bit, with one argument reduction.
inline void sincos(double x, double& s, double& c) {
  if (!std::isfinite(x)) {
    s = c = x - x;
    return;
  }
  if (std::fabs(x) < 0.78539816339744828) {  // |x| < pi/4: reduce() would give r = x, quadrant 0
    s = x == 0 ? x : detail::kernel_sin(x);
    c = detail::kernel_cos(x);
    return;
  }
  int q = 0;
  const double r = detail::reduce(x, q);
  const double ks = detail::kernel_sin(r), kc = detail::kernel_cos(r);
  switch (q) {
    case 0: s = ks; c = kc; break;
    case 1: s = kc; c = -ks; break;
    case 2: s = -ks; c = -kc; break;
    default: s = -kc; c = ks; break;
  }
  if (x == 0) s = x;  // keeps the sign of zero, as sin() does
}

inline double atan(double x) { return x < 0 ? -detail::atan_pos(-x) : detail::atan_pos(x); }

// The angle of (x, y) in (-pi, pi], signs of zeros as in C's atan2.
inline double atan2(double y, double x) {
  constexpr double kPi = 3.14159265358979311600e+00, kHalfPi = 1.57079632679489655800e+00;
  if (std::isnan(x) || std::isnan(y)) return x + y;
  if (y == 0) {
    if (std::signbit(x)) return std::signbit(y) ? -kPi : kPi;
    return y;  // +-0
  }
  if (x == 0) return y > 0 ? kHalfPi : -kHalfPi;
  if (std::isinf(x)) {
    const double a = std::isinf(y) ? 7.85398163397448278999e-01 : 0.0;  // pi/4 or 0
    if (x > 0) return y > 0 ? a : -a;
    return y > 0 ? kPi - a : a - kPi;
  }
  if (std::isinf(y)) return y > 0 ? kHalfPi : -kHalfPi;
  const double a = detail::atan_pos(std::fabs(y / x));
  if (x > 0) return y > 0 ? a : -a;
  return y > 0 ? kPi - a : a - kPi;
}

// acos of x in [-1, 1] (NaN outside), in [0, pi].
inline double acos(double x) {
  if (!(x >= -1.0 && x <= 1.0)) return (x - x) / (x - x);
  return atan2(std::sqrt((1.0 - x) * (1.0 + x)), x);
}

// sqrt(x^2 + y^2); no scaling (animation lengths are far from overflow).
inline double hypot(double x, double y) { return std::sqrt(x * x + y * y); }

// 2^x: 2^k by ldexp (exact), 2^f for |f| <= 1/2 by its series.
inline double exp2(double x) {
  if (std::isnan(x)) return x;
  if (x > 1024) return HUGE_VAL;
  if (x < -1100) return 0.0;
  const double k = std::floor(x + 0.5);
  const double t = (x - k) * 6.93147180559945286227e-01;  // f ln 2, |t| <= 0.347
  // e^t = sum t^n / n!, n <= 13 (the rest is below 1e-17), by Horner.
  static constexpr double kInvFact[] = {1.0, 1.0, 1.0 / 2, 1.0 / 6, 1.0 / 24, 1.0 / 120, 1.0 / 720, 1.0 / 5040,
                                        1.0 / 40320, 1.0 / 362880, 1.0 / 3628800, 1.0 / 39916800,
                                        1.0 / 479001600, 1.0 / 6227020800};
  double s = kInvFact[13];
  for (int n = 12; n >= 0; --n) s = kInvFact[n] + t * s;
  return std::ldexp(s, static_cast<int>(k));
}

// Float arguments: computed in double, rounded once.
inline float sin(float x) { return static_cast<float>(sin(static_cast<double>(x))); }
inline float cos(float x) { return static_cast<float>(cos(static_cast<double>(x))); }
inline void sincos(float x, float& s, float& c) {
  double ds = 0, dc = 0;
  sincos(static_cast<double>(x), ds, dc);
  s = static_cast<float>(ds);
  c = static_cast<float>(dc);
}
inline float atan2(float y, float x) {
  return static_cast<float>(atan2(static_cast<double>(y), static_cast<double>(x)));
}
inline float acos(float x) { return static_cast<float>(acos(static_cast<double>(x))); }
inline float hypot(float x, float y) {
  // Products of floats are exact in double: one rounding in the sum, one in sqrt.
  return static_cast<float>(std::sqrt(static_cast<double>(x) * x + static_cast<double>(y) * y));
}
inline float exp2(float x) { return static_cast<float>(exp2(static_cast<double>(x))); }

}  // namespace mc::anim::pm
