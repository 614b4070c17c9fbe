// Numbers read from JSON written elsewhere (a recording, a server, a
// spectator). nlohmann's get<int>() of 1e81, or get<float>() of 1e300, is
// undefined behaviour (a conversion out of range); these throw instead, so
// that the parsers' catch turns such a message into a refusal with a reason
// (proto_frame_decoder_fuzz found it with UBSan).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include <nlohmann/json.hpp>

namespace mc::proto {

// An integer of type T: a JSON integer, or a number without a fraction,
// within T's range.
template <class T>
T json_integer(const nlohmann::json& v) {
  static_assert(std::is_integral_v<T>);
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    if (u <= static_cast<std::uint64_t>(std::numeric_limits<T>::max())) return static_cast<T>(u);
  } else if (v.is_number_integer()) {
    const auto s = v.get<std::int64_t>();
    if (s >= static_cast<std::int64_t>(std::numeric_limits<T>::min()) &&
        (s < 0 || static_cast<std::uint64_t>(s) <= static_cast<std::uint64_t>(std::numeric_limits<T>::max())))
      return static_cast<T>(s);
  } else if (v.is_number_float()) {
    const double d = v.get<double>();
    if (std::isfinite(d) && d == std::trunc(d) && d >= static_cast<double>(std::numeric_limits<T>::min()) &&
        d <= static_cast<double>(std::numeric_limits<T>::max()))
      return static_cast<T>(d);
  } else {
    throw std::invalid_argument("an integer was expected, not " + std::string(v.type_name()));
  }
  throw std::out_of_range("number out of range: " + v.dump());
}

// A float: any JSON number within float's range.
inline float json_float(const nlohmann::json& v) {
  if (!v.is_number()) throw std::invalid_argument("a number was expected, not " + std::string(v.type_name()));
  const double d = v.get<double>();
  if (!std::isfinite(d) || std::fabs(d) > static_cast<double>(std::numeric_limits<float>::max()))
    throw std::out_of_range("number out of range: " + v.dump());
  return static_cast<float>(d);
}

}  // namespace mc::proto
