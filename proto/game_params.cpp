#include "proto/game_params.hpp"

#include <algorithm>
#include <charconv>

#include "proto/float_chars.hpp"

namespace mc {

double PlayerType::real_speed_max(double maxpower) const {
  const double by_dash = maxpower * dash_power_rate * effort_max / (1.0 - player_decay);
  return std::min(by_dash, player_speed_max);
}

std::optional<std::string> ParamTable::text(const std::string& key) const {
  auto it = values_.find(key);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

double ParamTable::number(const std::string& key, double fallback) const {
  auto it = values_.find(key);
  if (it == values_.end()) return fallback;
  const std::string& s = it->second;
  if (s == "true") return 1;
  if (s == "false") return 0;
  double v = 0;
  auto [end, ec] = from_chars_double(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return fallback;
  return v;
}

const PlayerType& GameParams::type(int id) const {
  static const PlayerType kDefault{};
  if (id < 0 || static_cast<std::size_t>(id) >= player_types.size()) return kDefault;
  return player_types[static_cast<std::size_t>(id)];
}

}  // namespace mc
