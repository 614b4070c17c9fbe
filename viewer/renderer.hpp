// Draws the 3D scene of one (interpolated) frame: sky, pitch, goals, the
// players' segments in their kits, blob shadows and the ball. One lit
// shader, three static meshes (unit cube, unit sphere, disc) drawn with a
// model matrix each, and the pitch built once per field (pitch_geometry).
// OpenGL 3.3 core, which Mesa's llvmpipe runs under Xvfb.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "proto/hello.hpp"
#include "proto/pose_frame.hpp"
#include "viewer/body_renderer.hpp"
#include "viewer/camera.hpp"
#include "viewer/gl_util.hpp"
#include "viewer/pitch_geometry.hpp"
#include "viewer/player_model.hpp"

namespace mc::viewer {

inline constexpr float kBallRadius = 0.13f;  // drawn a little larger than 0.085 m, as the page
inline const glm::vec3 kSkyColor{0.56f, 0.72f, 0.87f};

class Renderer {
 public:
  ~Renderer();
  // Needs a current GL 3.3 context; false + error otherwise.
  bool init(std::string& error);
  // Rebuilds the pitch for a field (a new hello).
  void set_field(const proto::FieldGeometry& field);
  // Sky only (no stream yet).
  void clear(int width, int height);
  // The whole scene. `hidden_slot` (first person) is not drawn; -1 = none.
  void draw(const PoseFrame& frame, const proto::Hello& hello, const PlayerModel& model, const Camera& camera,
            int width, int height, int hidden_slot, int selected_slot);

 private:
  void draw_mesh(const gl::Mesh& mesh, const glm::mat4& model, const glm::vec3& color, float alpha = 1.0f,
                 bool lit = true);
  // The shirt number on the back (large) and the front (small) of the chest
  // segment, as quads in the chest joint's local space; built once per
  // number and chest shape.
  const gl::Mesh& number_mesh(int number, const Segment& chest);

  GLuint program_ = 0;
  GLint u_mvp_ = -1, u_model_ = -1, u_tint_ = -1, u_use_tint_ = -1, u_alpha_ = -1, u_lit_ = -1;
  gl::Mesh cube_, sphere_, disc_, ground_, markings_, center_lines_;
  std::vector<ColoredBox> goals_;
  glm::mat4 view_proj_{1.0f};
  std::vector<glm::mat4> joints_;
  std::vector<SegmentInstance> segments_;
  std::map<int, std::unique_ptr<gl::Mesh>> numbers_;
  std::array<float, 6> numbers_chest_{};  // the chest size and centre the numbers were built for
  // Smooth skinned bodies for the server's skeleton (issue 20); boxes otherwise.
  BodyRenderer bodies_;
  std::string body_skeleton_;  // the skeleton the bodies were built for
};

}  // namespace mc::viewer
