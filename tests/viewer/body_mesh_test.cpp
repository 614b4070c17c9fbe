// The viewer's body is the page's, vertex for vertex: both generators against
// one summary (tests/web/data/body_summary.json, also checked by
// tests/web/body_model.test.mjs), on anim's skeleton (whose copy the page's
// test reads is checked here too). Then skinning: at rest the mesh stays put,
// a turned joint carries its vertices.
#include "viewer/body_mesh.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "anim/human_skeleton.hpp"
#include "viewer/player_model.hpp"

namespace mc::viewer {
namespace {

nlohmann::json read_json(const std::string& rel) {
  std::ifstream in(std::string(MATCHCAST_SOURCE_DIR) + "/" + rel);
  std::stringstream ss;
  ss << in.rdbuf();
  return nlohmann::json::parse(ss.str());
}

TEST(BodyMesh, TheViewersBodyIsThePagesVertexForVertex) {
  const auto golden = read_json("tests/web/data/body_summary.json");
  for (int lod = 0; lod < 2; ++lod) {
    std::string error;
    const auto mesh = build_body(body_spec_json(), anim::human_skeleton(), lod, error);
    ASSERT_TRUE(mesh) << error;
    const BodySummary s = summarize(*mesh);
    const auto& g = golden.at(static_cast<std::size_t>(lod));
    EXPECT_EQ(s.vertices, g["vertices"].get<std::size_t>()) << "lod " << lod;
    EXPECT_EQ(s.triangles, g["triangles"].get<std::size_t>());
    for (int k = 0; k < 3; ++k) {
      EXPECT_DOUBLE_EQ(s.min[static_cast<std::size_t>(k)], g["min"][static_cast<std::size_t>(k)].get<double>());
      EXPECT_DOUBLE_EQ(s.max[static_cast<std::size_t>(k)], g["max"][static_cast<std::size_t>(k)].get<double>());
    }
    EXPECT_NEAR(s.position_sum, g["positionSum"].get<double>(), 0.0015);
    EXPECT_EQ(s.bone_region_sum, g["boneRegionSum"].get<long long>());
    EXPECT_EQ(s.index_sum, g["indexSum"].get<long long>());
  }
}

TEST(BodyMesh, ThePagesSkeletonCopyIsAnimsSkeleton) {
  const auto copy = read_json("tests/web/data/human_skeleton.json");
  const SkeletonDef& s = anim::human_skeleton();
  EXPECT_EQ(copy["name"], s.name);
  ASSERT_EQ(copy["joints"].size(), s.joints.size());
  for (std::size_t i = 0; i < s.joints.size(); ++i) {
    EXPECT_EQ(copy["joints"][i]["name"], s.joints[i].name);
    EXPECT_EQ(copy["joints"][i]["parent"].get<int>(), s.joints[i].parent);
    EXPECT_EQ(copy["joints"][i]["dofs"], s.joints[i].dofs);
    for (int k = 0; k < 3; ++k)
      EXPECT_FLOAT_EQ(copy["joints"][i]["offset"][k].get<float>(), s.joints[i].offset_ls[static_cast<std::size_t>(k)]);
  }
}

TEST(BodyMesh, AnotherSkeletonGetsNoBody) {
  SkeletonDef other;
  other.name = "two-joints";
  other.joints.push_back(JointDef{"root", -1, {0, 0, 0}, "y", {{-10, 10}}, {}});
  std::string error;
  EXPECT_FALSE(build_body(body_spec_json(), other, 0, error));
  EXPECT_NE(error.find("joint"), std::string::npos) << error;
  EXPECT_FALSE(build_body("{not json", anim::human_skeleton(), 0, error));
}

TEST(BodyMesh, SkinningFollowsTheJoints) {
  std::string error;
  const auto mesh = build_body(body_spec_json(), anim::human_skeleton(), 0, error);
  ASSERT_TRUE(mesh) << error;
  const auto rest = rest_positions(anim::human_skeleton());
  const auto normals = rest_normals(*mesh);
  PlayerModel model(anim::human_skeleton());
  PlayerPose pose;
  pose.state = 1;
  pose.unum = 9;
  pose.x = 10;
  pose.y = -5;
  pose.z = 1.0f;
  std::vector<glm::mat4> joints;
  ASSERT_TRUE(model.joints(pose, joints));
  std::vector<glm::vec3> pos, nrm;
  skin_body(*mesh, rest, joints, normals, pos, nrm);
  // At rest, facing +x (heading 0): scene = (x, z + y_body, y + z_body).
  double worst = 0;
  for (std::size_t i = 0; i < pos.size(); ++i) {
    const glm::dvec3& r = mesh->positions[i];
    worst = std::max(worst, glm::length(glm::dvec3(pos[i]) - glm::dvec3(10 + r.x, 1.0 + r.y, -5 + r.z)));
  }
  EXPECT_LT(worst, 1e-4);
  // The soles are on the grass, the head up at about 1.8 m.
  float low = 9, high = -9;
  for (const auto& p : pos) {
    low = std::min(low, p.y);
    high = std::max(high, p.y);
  }
  EXPECT_NEAR(low, 0.0f, 0.01f);
  EXPECT_NEAR(high, 1.84f, 0.03f);
  // The right knee bent 90 degrees: the right boot's toe rises behind the body.
  pose.angles[27] = -90;  // r_shin "z" (human_skeleton.hpp kRKnee)
  ASSERT_TRUE(model.joints(pose, joints));
  skin_body(*mesh, rest, joints, normals, pos, nrm);
  float r_boot_min_x = 99;
  for (std::size_t i = 0; i < pos.size(); ++i)
    if (mesh->regions[mesh->region[i]] == "boot" && mesh->positions[i].z > 0) r_boot_min_x = std::min(r_boot_min_x, pos[i].x);
  EXPECT_LT(r_boot_min_x, 10 - 0.3f) << "the shin swung back";
}

}  // namespace
}  // namespace mc::viewer
