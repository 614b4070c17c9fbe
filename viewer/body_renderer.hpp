// Draws the players' skinned bodies (viewer/body_mesh.hpp) with the
// renderer's lit shader: each frame every visible player is skinned on the
// CPU and streamed to one buffer, drawn indexed; near players (within 28 m
// of the camera) get the detailed mesh and their numbers (back, chest,
// shorts), far ones the half-resolution mesh. OpenGL 3.3 core.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <vector>

#include <glm/mat4x4.hpp>

#include "proto/skeleton.hpp"
#include "viewer/body_mesh.hpp"
#include "viewer/gl_util.hpp"
#include "viewer/player_model.hpp"

namespace mc::viewer {

inline constexpr float kBodyFarMetres = 28.0f;

class BodyRenderer {
 public:
  BodyRenderer() = default;
  BodyRenderer(const BodyRenderer&) = delete;
  BodyRenderer& operator=(const BodyRenderer&) = delete;
  ~BodyRenderer();

  // Builds the meshes for a skeleton (a new hello); false when there is no
  // body for it: the renderer then draws the skeleton's boxes.
  bool set_skeleton(const SkeletonDef& skeleton);
  bool ready() const { return ready_; }

  // One player, with the renderer's program bound and its u_mvp / u_model
  // set for scene space (identity model) and u_use_tint 0. `far` picks the
  // level of detail.
  void draw_body(const PlayerPose& pose, const std::vector<glm::mat4>& joints, const Kit& kit, bool far);
  // The player's numbers, each drawn with `draw(mesh, joint matrix, colour)`.
  template <typename Draw>
  void draw_numbers(const PlayerPose& pose, const std::vector<glm::mat4>& joints, const Kit& kit, Draw&& draw) {
    for (std::size_t d = 0; d < numbers_.size(); ++d) {
      const BodyNumber& n = numbers_[d];
      if (n.joint < 0 || static_cast<std::size_t>(n.joint) >= joints.size()) continue;
      draw(number_mesh(pose.unum, d), joints[static_cast<std::size_t>(n.joint)], d == numbers_.size() - 1 ? shorts_ink(kit) : kit.number);
    }
  }

 private:
  struct Level {
    BodyMesh mesh;
    std::vector<glm::vec3> normals;
    GLuint vao = 0, vbo = 0, ebo = 0;
  };
  const gl::Mesh& number_mesh(int unum, std::size_t decal);
  static glm::vec3 shorts_ink(const Kit& kit);
  void release();

  bool ready_ = false;
  std::array<Level, 2> levels_;
  std::vector<glm::dvec3> rest_;
  std::vector<BodyNumber> numbers_;
  std::array<std::array<glm::vec3, 2>, 24> tones_{};  // [side * 12 + unum]: skin, hair
  std::map<std::pair<int, std::size_t>, std::unique_ptr<gl::Mesh>> number_meshes_;
  std::vector<glm::vec3> pos_, normal_;
  std::vector<float> interleaved_;
};

}  // namespace mc::viewer
