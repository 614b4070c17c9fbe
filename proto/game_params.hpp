// Parameters rcssserver announces at the start of a log or monitor session:
// `(server_param ...)`, `(player_param ...)` and one `(player_type ...)` per
// heterogeneous type. Later stages read them at runtime instead of
// hard-coding them (older servers differ, e.g. back_dash_rate 0.6 vs 0.7).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace mc {

// One heterogeneous player type. Defaults are rcssserver 19's type 0
// (src/heteroplayer.cpp, src/serverparam.cpp), used when a feed sends none.
struct PlayerType {
  int id = 0;
  double player_speed_max = 1.05;   // m/cycle
  double stamina_inc_max = 45;
  double player_decay = 0.4;
  double inertia_moment = 5;
  double dash_power_rate = 0.006;
  double player_size = 0.3;         // m, radius
  double kickable_margin = 0.7;     // m
  double kick_rand = 0.1;
  double extra_stamina = 50;
  double effort_max = 1;
  double effort_min = 0.6;
  double kick_power_rate = 0.027;
  double foul_detect_probability = 0.5;
  double catchable_area_l_stretch = 1;

  // Top speed the dash model allows: maxpower * dash_power_rate * effort_max
  // / (1 - player_decay), capped by player_speed_max (src/heteroplayer.cpp).
  double real_speed_max(double maxpower = 100) const;
  // Distance from the body centre at which the ball can be kicked.
  double kickable_distance(double ball_size = 0.085) const {
    return player_size + kickable_margin + ball_size;
  }
};

// A flat key -> value table of the textual parameter values, with typed
// accessors. Strings keep their quotes removed; booleans are "0"/"1" or
// "true"/"false" as the feed sent them.
class ParamTable {
 public:
  void set(std::string key, std::string value) { values_[std::move(key)] = std::move(value); }
  bool has(const std::string& key) const { return values_.count(key) != 0; }
  std::optional<std::string> text(const std::string& key) const;
  // Numeric value, or `fallback` when absent or not a number.
  double number(const std::string& key, double fallback) const;
  const std::map<std::string, std::string>& all() const { return values_; }
  bool empty() const { return values_.empty(); }

 private:
  std::map<std::string, std::string> values_;
};

struct GameParams {
  ParamTable server;
  ParamTable player;
  std::vector<PlayerType> player_types;  // indexed by id

  // The type with this id, or rcssserver's default type when unknown.
  const PlayerType& type(int id) const;
  double ball_size() const { return server.number("ball_size", 0.085); }
  double goal_width() const { return server.number("goal_width", 14.02); }
  double simulator_step_ms() const { return server.number("simulator_step", 100); }
};

}  // namespace mc
