// The hello control message: the first text WebSocket message a client
// receives, and the first record of a recording. It carries everything a
// client needs before it can decode or draw a pose frame (SPEC.md "hello").
#pragma once

#include <map>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "proto/frame_header.hpp"
#include "proto/game_params.hpp"
#include "proto/skeleton.hpp"

namespace mc::proto {

// Field markings in metres, rcssserver's fixed geometry (src/field.cpp /
// serverparam.h: PITCH_LENGTH 105, PITCH_WIDTH 68, ...); goal width and
// ball size come from server_param when known.
struct FieldGeometry {
  double length = 105.0;
  double width = 68.0;
  double goal_width = 14.02;
  double goal_depth = 2.44;
  double goal_height = 2.44;          // not in 2D; drawn at the FIFA height
  double penalty_area_length = 16.5;
  double penalty_area_width = 40.32;
  double goal_area_length = 5.5;
  double goal_area_width = 18.32;
  double center_circle_radius = 9.15;
  double penalty_spot_distance = 11.0;
  double corner_arc_radius = 1.0;
  double ball_radius = 0.085;
};

struct TeamHello {
  std::string name;            // "" when not known yet
  std::string color = "#ffffff";   // "#rrggbb", shirt
  std::string color2 = "#000000";  // "#rrggbb", shorts/numbers
};

struct Hello {
  int protocol_major = kProtocolMajor;
  int protocol_minor = kProtocolMinor;
  double frame_rate = 20.0;      // pose frames per second
  int keyframe_interval = 20;    // frames between keyframes
  SkeletonDef skeleton;
  FieldGeometry field;
  TeamHello left, right;
  // The server parameters clients use, by rcssserver's names (e.g.
  // "half_time", "simulator_step", "ball_size", "player_size").
  std::map<std::string, double> server_params;
  std::string match_id;          // free text naming the match ("" if none)
};

// Fills field geometry and the client-relevant server parameters from
// what ingest read at the start of the game.
void fill_from_params(const GameParams& params, Hello& hello);

nlohmann::json hello_to_json_value(const Hello& hello);
std::string to_json(const Hello& hello);  // one line, with "type":"hello"

// False with `error` when the text is not JSON, not a hello, the major
// protocol version is not kProtocolMajor, or a required field is missing or
// has the wrong type. `out` is unspecified after false.
bool hello_from_json(std::string_view text, Hello& out, std::string& error);

// Skeleton JSON, shared by hello and tests.
nlohmann::json skeleton_to_json(const SkeletonDef& skeleton);
bool skeleton_from_json(const nlohmann::json& j, SkeletonDef& out, std::string& error);

}  // namespace mc::proto
