// The pitch as triangles: grass with mown stripes, the markings, and the
// goals' frames as boxes, all from the hello's field description (the
// defaults are rcssserver's fixed geometry). Scene space as in camera.hpp.
// The page draws the same things (web/src/scene/pitch.js). No OpenGL here.
#pragma once

#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "proto/hello.hpp"

namespace mc::viewer {

struct Vertex {
  glm::vec3 pos, normal, color;
};

struct ColoredBox {
  glm::mat4 model;  // unit cube [-0.5, 0.5]^3 -> scene
  glm::vec3 color;
};

struct PitchGeometry {
  std::vector<Vertex> ground;     // grass and surroundings (triangles, y = 0)
  std::vector<Vertex> markings;   // white lines (triangles, drawn on the grass)
  // The same lines' centres as GL_LINES pairs: drawn over the triangles so
  // that a far line stays at least one pixel wide instead of breaking up.
  std::vector<Vertex> center_lines;
  std::vector<ColoredBox> goals;  // posts, crossbars, net frames
};

inline constexpr float kLineWidth = 0.15f;  // m; a little wider than the 0.12 paint, to read from afar
inline const glm::vec3 kGrassLight{0.29f, 0.60f, 0.24f};
inline const glm::vec3 kGrassDark{0.26f, 0.56f, 0.22f};

PitchGeometry build_pitch(const proto::FieldGeometry& field);

}  // namespace mc::viewer
