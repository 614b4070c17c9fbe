#include "proto/hello.hpp"

#include <gtest/gtest.h>

#include "tests/proto/support/synthetic.hpp"

namespace mc::proto {
namespace {

Hello sample_hello() {
  Hello h;
  h.skeleton = testing::humanoid_skeleton();
  h.left = {"HELIOS_A", "#ffdd00", "#000000"};
  h.right = {"HELIOS_B", "#2255ff", "#ffffff"};
  h.match_id = "test";
  GameParams params;
  params.server.set("half_time", "300");
  params.server.set("goal_width", "14.02");
  params.server.set("unrelated_param", "1");
  fill_from_params(params, h);
  return h;
}

TEST(Hello, RoundTripsThroughJson) {
  const Hello h = sample_hello();
  const std::string text = to_json(h);
  EXPECT_NE(text.find("\"type\":\"hello\""), std::string::npos);
  Hello back;
  std::string error;
  ASSERT_TRUE(hello_from_json(text, back, error)) << error;
  EXPECT_EQ(back.protocol_major, kProtocolMajor);
  EXPECT_EQ(back.left.name, "HELIOS_A");
  EXPECT_EQ(back.right.color, "#2255ff");
  EXPECT_EQ(back.match_id, "test");
  EXPECT_EQ(back.server_params.at("half_time"), 300.0);
  EXPECT_EQ(back.server_params.count("unrelated_param"), 0u);
  EXPECT_DOUBLE_EQ(back.field.goal_width, 14.02);
  ASSERT_EQ(back.skeleton.joints.size(), h.skeleton.joints.size());
  EXPECT_EQ(back.skeleton.dof_count(), h.skeleton.dof_count());
  for (std::size_t i = 0; i < h.skeleton.joints.size(); ++i) {
    EXPECT_EQ(back.skeleton.joints[i].name, h.skeleton.joints[i].name);
    EXPECT_EQ(back.skeleton.joints[i].parent, h.skeleton.joints[i].parent);
    EXPECT_EQ(back.skeleton.joints[i].limits, h.skeleton.joints[i].limits);
    EXPECT_EQ(back.skeleton.joints[i].offset_ls, h.skeleton.joints[i].offset_ls);
  }
}

TEST(Hello, RefusesUnknownMajorVersion) {
  auto j = hello_to_json_value(sample_hello());
  j["protocol"]["major"] = 9;
  Hello back;
  std::string error;
  EXPECT_FALSE(hello_from_json(j.dump(), back, error));
  EXPECT_NE(error.find("unsupported protocol major version 9"), std::string::npos) << error;
}

TEST(Hello, RefusesBadInputWithAClearError) {
  Hello back;
  std::string error;
  EXPECT_FALSE(hello_from_json("{not json", back, error));
  EXPECT_FALSE(error.empty());
  EXPECT_FALSE(hello_from_json(R"({"type":"kick"})", back, error));
  EXPECT_NE(error.find("hello"), std::string::npos);
  auto j = hello_to_json_value(sample_hello());
  j["skeleton"]["joints"][2]["parent"] = 7;  // a parent after its child
  EXPECT_FALSE(hello_from_json(j.dump(), back, error));
  EXPECT_NE(error.find("skeleton"), std::string::npos) << error;
  j = hello_to_json_value(sample_hello());
  j.erase("frame_rate");
  EXPECT_FALSE(hello_from_json(j.dump(), back, error));
  // A whole hello, then a NUL and junk (nlohmann's parser stopped at the NUL).
  const std::string good = to_json(sample_hello());
  ASSERT_TRUE(hello_from_json(good, back, error)) << error;
  EXPECT_FALSE(hello_from_json(good + std::string(1, '\0') + "junk", back, error));
  EXPECT_EQ(error, "hello is not a JSON object");
}

}  // namespace
}  // namespace mc::proto
