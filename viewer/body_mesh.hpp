// The players' bodies in the native viewer (issue 20): the same generated
// mesh as the page (web/src/model/body_geometry.js), from the same
// description (web/assets/body.json, built into the viewer), vertex for
// vertex. Rings around the skeleton's bones and an ellipsoid head, in the
// skeleton's rest pose, each vertex with up to two bones and a region that
// the kit colours; skinned on the CPU each frame (1,217 vertices a player
// near, 573 far). No OpenGL here: body_renderer draws what this makes, and
// the tests check it.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "proto/skeleton.hpp"
#include "proto/world_state.hpp"

namespace mc::viewer {

// The description as the viewer was built with it.
std::string_view body_spec_json();

struct BodyNumber {
  int joint = -1;
  glm::vec3 at{0.0f};
  float size = 0;
  int face = 1;  // +1: facing +X (the front), -1: the back
};

struct BodyMesh {
  std::vector<glm::dvec3> positions;           // rest pose, body space
  std::vector<std::array<int, 2>> bones;       // joint indices
  std::vector<std::array<double, 2>> weights;  // their weights (sum 1)
  std::vector<std::uint8_t> region;            // index into `regions`
  std::vector<std::uint32_t> index;            // triangles
  std::vector<std::string> regions;            // "shirt", "shorts", "sock", "boot", "skin", "hair"
};

struct BodySummary {
  std::size_t vertices = 0, triangles = 0;
  std::array<double, 3> min{}, max{};
  double position_sum = 0;
  long long bone_region_sum = 0, index_sum = 0;
};

// The mesh of level `lod` (0 near, 1 far) for `skeleton`; nullopt with
// `error` when the description does not parse or names a joint the
// skeleton lacks (another skeleton: the viewer draws its boxes then).
std::optional<BodyMesh> build_body(std::string_view spec_json, const SkeletonDef& skeleton, int lod,
                                   std::string& error);
// The numbers (back, chest, shorts) in the skeleton's joints.
std::vector<BodyNumber> body_numbers(std::string_view spec_json, const SkeletonDef& skeleton);
// The counts, bounds and sums both generators must agree on (rounded like the page's).
BodySummary summarize(const BodyMesh& mesh);
// A player's skin and hair tones ("#rrggbb" -> 0..1), as the page picks them.
std::array<glm::vec3, 2> body_tones(std::string_view spec_json, Side side, int unum);

// The rest positions of the joints (the root at the origin).
std::vector<glm::dvec3> rest_positions(const SkeletonDef& skeleton);

// Skins `mesh` with the joints' scene transforms (PlayerModel::joints):
// positions and normals in scene space, per vertex.
void skin_body(const BodyMesh& mesh, const std::vector<glm::dvec3>& rest, const std::vector<glm::mat4>& joints,
               const std::vector<glm::vec3>& rest_normals, std::vector<glm::vec3>& out_pos,
               std::vector<glm::vec3>& out_normal);
// Area-weighted vertex normals of the rest mesh.
std::vector<glm::vec3> rest_normals(const BodyMesh& mesh);

}  // namespace mc::viewer
