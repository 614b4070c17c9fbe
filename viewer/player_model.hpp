// A player as boxes and spheres: the hello's skeleton, posed by a frame,
// placed on the pitch, dressed in the team's kit. Forward kinematics is
// anim's LocalToModelJob (the same maths the server animates with); this
// file adds the field placement and the segment shapes, as the web page
// does (web/src/scene/players.js):
//   root at scene (x, 0, y) turned by -heading about +Y, the pelvis at
//   height z, then M_j = M_parent * T(offset) * R_local.
// No OpenGL here: the renderer draws the segments, and tests project them.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "proto/hello.hpp"
#include "proto/pose_frame.hpp"

namespace mc::viewer {

// What a segment is dressed in, guessed from its joint's name like the page.
enum class Part { Shirt, Shorts, Skin, Sock, Boot };
Part part_of(std::string_view joint_name);

// "#rrggbb" or "#rgb" -> 0..1 RGB; `fallback` for anything else.
glm::vec3 parse_color(std::string_view text, glm::vec3 fallback);

struct Kit {
  glm::vec3 shirt, shorts, sock, skin, boot, number;
  glm::vec3 color(Part part) const;
};
// The field players' and the goalie's kits of one side (the page's defaults
// when the hello has no colour; goalies wear the page's goalie colours).
Kit team_kit(const proto::TeamHello& team, Side side, bool goalie);

struct SegmentInstance {
  glm::mat4 model;         // unit cube [-0.5, 0.5]^3 or unit sphere -> scene
  bool sphere = false;
  Part part = Part::Shirt;
};

class PlayerModel {
 public:
  explicit PlayerModel(const SkeletonDef& skeleton);

  // Joint transforms in scene space for one player; false when the skeleton
  // cannot be posed (an empty or malformed skeleton).
  bool joints(const PlayerPose& pose, std::vector<glm::mat4>& out) const;
  // Every drawable segment of one player (after joints()).
  void segments(const std::vector<glm::mat4>& joints, std::vector<SegmentInstance>& out) const;

  int head_joint() const { return head_; }
  // The joint wearing the shirt number: the largest shirt box (-1 if none).
  int chest_joint() const { return chest_; }
  // Scene centre of a joint's segment (the chest centre is where a test
  // expects the shirt colour).
  glm::vec3 segment_center(const std::vector<glm::mat4>& joints, int joint) const;
  const SkeletonDef& skeleton() const { return skeleton_; }

 private:
  SkeletonDef skeleton_;
  std::vector<Part> parts_;
  int head_ = -1, chest_ = -1;
};

// Disconnected players (state 0) are parked off the pitch and not drawn.
inline bool player_visible(const PlayerPose& p) { return p.state != 0 && p.unum != 0; }

}  // namespace mc::viewer
