// Decimal text -> double, without locale, allocation or copies, and the same
// on every build of Matchcast: fast_float (Debian's libfast-float-dev,
// header-only), the reference implementation of std::from_chars for
// floating point. It is used instead of std::from_chars because the
// WebAssembly build's libc++ 13 (emscripten 3.1.6) has no floating-point
// from_chars; one parser for both builds keeps their frames identical.
//
// Behaves like std::from_chars(first, last, v) (chars_format::general): no
// leading whitespace or '+', "inf"/"nan" accepted, `ptr` just past the last
// character used. As with std::from_chars, a value too large for a double is
// std::errc::result_out_of_range and leaves `v` unchanged, and so is one
// too small, rounding to zero (fast_float alone returns infinity or zero).
#pragma once

#include <charconv>
#include <cmath>
#include <system_error>

#include <fast_float/fast_float.h>

namespace mc {

inline std::from_chars_result from_chars_double(const char* first, const char* last, double& v) {
  double x = 0;
  const auto r = fast_float::from_chars(first, last, x);
  if (r.ec != std::errc()) return {r.ptr, r.ec};
  // Infinity from finite digits is an overflow; spelled "inf" it is a value.
  if (std::isinf(x)) {
    const char c = *first == '-' ? (first + 1 < last ? first[1] : '\0') : *first;
    if (c != 'i' && c != 'I') return {r.ptr, std::errc::result_out_of_range};
  }
  // Zero from a non-zero mantissa is an underflow.
  if (x == 0) {
    for (const char* p = first; p < r.ptr && *p != 'e' && *p != 'E'; ++p)
      if (*p >= '1' && *p <= '9') return {r.ptr, std::errc::result_out_of_range};
  }
  v = x;
  return {r.ptr, std::errc()};
}

}  // namespace mc
