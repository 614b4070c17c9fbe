#include "anim/mocap/bvh_parser.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "anim/mocap/io/clip_files.hpp"

using namespace mc::anim::mocap;

namespace {

// Two joints + an end site, with the quirks of the CMU files: mixed CRLF/LF,
// tabs, a trailing space on the root CHANNELS, "Frames:\t3", ".0083333",
// "End Site", and a cgspeed-style T-pose as frame 0. Offsets in CMU units.
std::string quirky_bvh(const char* joint_order = "Zrotation Yrotation Xrotation") {
  std::string s =
      "HIERARCHY\r\nROOT Hips\n{\r\n\tOFFSET 0 0 0\n"
      "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation \r\n"
      "\tJOINT Leg\n\t{\r\n\t\tOFFSET 0 -10 0\n\t\tCHANNELS 3 ";
  s += joint_order;
  s += "\r\n\t\tEnd Site\n\t\t{\r\n\t\t\tOFFSET 0 -5 0\n\t\t}\n\t}\r\n}\n"
       "MOTION\r\nFrames:\t3\nFrame Time: .0083333\r\n"
       "0 0 0 0 0 0 -21 0 8\n"            // T-pose: root rotation 0, whole small numbers
       "1 20 3 0 0 0 90 0 0\r\n"          // Leg turned 90 deg about its first axis
       "2 20 3 0 0 0 0 90 0\n";
  return s;
}

}  // namespace

TEST(BvhParser, QuirkyTextParsesWithUnitsAndDropsTPose) {
  const auto r = parse_bvh(quirky_bvh());
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_TRUE(r.dropped_tpose);
  const auto& c = r.clip;
  ASSERT_EQ(c.skeleton.size(), 3);
  EXPECT_EQ(c.skeleton.names[2], "Leg_end");
  EXPECT_TRUE(c.skeleton.end_site[2]);
  EXPECT_EQ(c.frames, 2);
  EXPECT_NEAR(c.frame_time, 0.0083333, 1e-9);
  EXPECT_NEAR(c.skeleton.offsets[1].y, -10 * kCmuUnitToMetres, 1e-6);
  EXPECT_NEAR(c.root_position[0].x, 1 * kCmuUnitToMetres, 1e-6);
  EXPECT_NEAR(c.root_position[0].y, 20 * kCmuUnitToMetres, 1e-6);
}

TEST(BvhParser, RotationOrderComesFromChannels) {
  // Frame 1 turns Leg by 90 deg about Z (first channel): the end site at
  // -5 Y swings to +5 X. With "Xrotation ..." first, the same value is about X.
  const auto zyx = parse_bvh(quirky_bvh("Zrotation Yrotation Xrotation"));
  const auto xzy = parse_bvh(quirky_bvh("Xrotation Zrotation Yrotation"));
  ASSERT_TRUE(zyx.ok && xzy.ok);
  std::vector<glm::vec3> p;
  forward_kinematics(zyx.clip, 0, p);
  const float u = static_cast<float>(kCmuUnitToMetres);
  EXPECT_NEAR(p[2].x - p[1].x, 5 * u, 1e-5);
  EXPECT_NEAR(p[2].y - p[1].y, 0, 1e-5);
  forward_kinematics(xzy.clip, 0, p);
  EXPECT_NEAR(p[2].x - p[1].x, 0, 1e-5);
  EXPECT_NEAR(std::fabs(p[2].z - p[1].z), 5 * u, 1e-5);
}

TEST(BvhParser, KeepsFrameZeroWhenItIsNotATPose) {
  std::string s = quirky_bvh();
  s.replace(s.find("-21 0 8"), 7, "-21.5 0 8");
  const auto r = parse_bvh(s);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_FALSE(r.dropped_tpose);
  EXPECT_EQ(r.clip.frames, 3);
}

TEST(BvhParser, MalformedInputGivesRowAndColumn) {
  std::string bad = quirky_bvh();
  bad.replace(bad.find("OFFSET 0 -10 0"), 14, "OFFSET 0 -1x 0");
  auto r = parse_bvh(bad);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("8:12:"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("number"), std::string::npos) << r.error;
  // Truncated motion, missing brace, unknown channel, too many values, empty.
  std::string t = quirky_bvh();
  EXPECT_FALSE(parse_bvh(t.substr(0, t.size() - 6)).ok);
  std::string nb = quirky_bvh();
  nb.erase(nb.find("{"), 1);
  EXPECT_FALSE(parse_bvh(nb).ok);
  std::string uc = quirky_bvh();
  uc.replace(uc.find("Xrotation"), 9, "Wrotation");
  EXPECT_FALSE(parse_bvh(uc).ok);
  EXPECT_FALSE(parse_bvh(quirky_bvh() + " 7").ok);
  EXPECT_FALSE(parse_bvh("").ok);
  EXPECT_FALSE(parse_bvh("HIERARCHY\nROOT").ok);
}

TEST(BvhParser, HostileNestingIsBounded) {
  std::string s = "HIERARCHY\nROOT a\n{\nOFFSET 0 0 0\nCHANNELS 0\n";
  for (int i = 0; i < 100000; ++i) s += "JOINT j\n{\nOFFSET 0 0 0\nCHANNELS 0\n";
  const auto r = parse_bvh(s);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("too many joints"), std::string::npos) << r.error;
}

TEST(BvhParser, RealCmuClipsLoad) {
  const std::string dir = std::string(MATCHCAST_MOCAP_DIR) + "/";
  struct Case { const char* file; int frames_in_header; int joints; bool tpose; };
  for (const Case c : {Case{"cmu_10_04.bvh", 550, 38, true}, Case{"cmu_10_03.bvh", 363, 38, true},
                       Case{"cmu_11_01_dazfriendly.bvh", 598, 0, false}}) {
    MocapClip clip;
    std::string error;
    ASSERT_TRUE(io::load_bvh(dir + c.file, clip, error)) << error;
    EXPECT_EQ(clip.frames, c.frames_in_header - (c.tpose ? 1 : 0)) << c.file;
    if (c.joints) {
      EXPECT_EQ(clip.skeleton.size(), c.joints) << c.file;  // 31 joints + 7 end sites
    }
    EXPECT_NEAR(clip.frame_time, 1.0 / 120, 1e-5);
  }
  // Subject 10's T-pose is 1.52 m from the head end site to the toe.
  std::string text, error;
  ASSERT_TRUE(io::read_file(dir + "cmu_10_04.bvh", text, error));
  BvhOptions keep;
  keep.drop_cgspeed_tpose = false;
  const auto r = parse_bvh(text, keep);
  ASSERT_TRUE(r.ok);
  std::vector<glm::vec3> p;
  forward_kinematics(r.clip, 0, p);
  const float top = p[static_cast<std::size_t>(r.clip.skeleton.find("Head_end"))].y;
  const float toe = p[static_cast<std::size_t>(r.clip.skeleton.find("LeftToeBase_end"))].y;
  EXPECT_NEAR(top - toe, 1.52, 0.02);
}
