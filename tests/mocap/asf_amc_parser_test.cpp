#include "anim/mocap/asf_amc_parser.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "anim/mocap/io/clip_files.hpp"

using namespace mc::anim::mocap;

namespace {

// Root + lfemur (down, axis rotated 90 deg about Z so its local X is world Y)
// + ltibia, CRLF line endings, units length 0.45.
const char* kAsf =
    "# test\r\n:version 1.10\r\n:name T\r\n:units\r\n  mass 1.0\r\n  length 0.45\r\n  angle deg\r\n"
    ":root\r\n   order TX TY TZ RX RY RZ\r\n   axis XYZ\r\n   position 0 0 0  \r\n   orientation 0 0 0 \r\n"
    ":bonedata\r\n  begin\r\n     id 1\r\n     name lfemur\r\n     direction 0 -1 0\r\n     length 10\r\n"
    "     axis 0 0 90 XYZ\r\n    dof rx ry rz\r\n    limits (-160.0 20.0)\r\n           (-70.0 70.0)\r\n"
    "           (-60.0 70.0)\r\n  end\r\n  begin\r\n     id 2\r\n     name ltibia\r\n     direction 0 -1 0\r\n"
    "     length 10\r\n     axis 0 0 0 XYZ\r\n    dof rx\r\n  end\r\n"
    ":hierarchy\r\n  begin\r\n    root lfemur\r\n    lfemur ltibia\r\n  end\r\n";

}  // namespace

TEST(AsfAmcParser, SyntheticSkeletonAndMotion) {
  const auto asf = parse_asf(kAsf);
  ASSERT_TRUE(asf.ok) << asf.error;
  ASSERT_EQ(asf.skeleton.bones.size(), 2u);
  EXPECT_EQ(asf.skeleton.bones[0].name, "LeftUpLeg");  // renamed to the cgspeed name
  EXPECT_EQ(asf.skeleton.bones[1].parent, 0);
  // Frame 1: rest. Frame 2: lfemur rx = 90 about its axis frame, whose X is
  // world Y (axis 0 0 90): a twist about the bone itself, so the knee stays;
  // ltibia rx = 90 about world X swings the shin to +Z or -Z.
  const char* amc = "#!OML:ASF t\r\n:FULLY-SPECIFIED\n:DEGREES\r\n1\r\nroot 0 20 0 0 0 0\r\nlfemur 0 0 0\nltibia 0\r\n"
                    "2\nroot 1 20 0 0 0 0\nlfemur 90 0 0\r\nltibia 90\r\n";
  const auto r = parse_amc(amc, asf.skeleton);
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(r.clip.frames, 2);
  const float u = static_cast<float>(0.0254 / 0.45);
  std::vector<glm::vec3> p;
  forward_kinematics(r.clip, 0, p);
  const int knee = r.clip.skeleton.find("LeftLeg"), ankle = r.clip.skeleton.find("LeftLeg_end");
  ASSERT_GE(knee, 0);
  ASSERT_GE(ankle, 0);
  EXPECT_NEAR(p[0].y, 20 * u, 1e-5);
  EXPECT_NEAR(p[static_cast<std::size_t>(knee)].y, 10 * u, 1e-5);
  EXPECT_NEAR(p[static_cast<std::size_t>(ankle)].y, 0, 1e-5);
  forward_kinematics(r.clip, 1, p);
  EXPECT_NEAR(p[0].x, 1 * u, 1e-5);
  EXPECT_NEAR(p[static_cast<std::size_t>(knee)].y, 10 * u, 1e-4);       // twist only
  EXPECT_NEAR(p[static_cast<std::size_t>(ankle)].y, 10 * u, 1e-4);      // shin horizontal
  const glm::vec3 shin = p[static_cast<std::size_t>(ankle)] - p[static_cast<std::size_t>(knee)];
  EXPECT_NEAR(std::hypot(shin.x, shin.z), 10 * u, 1e-4);
}

TEST(AsfAmcParser, BadInputIsAnError) {
  const auto asf = parse_asf(kAsf);
  ASSERT_TRUE(asf.ok);
  EXPECT_FALSE(parse_amc("1\nroot 0 0 0 0 0\n", asf.skeleton).ok);           // 5 root values
  EXPECT_FALSE(parse_amc("1\nroot 0 0 0 0 0 0\nnose 1\n", asf.skeleton).ok);  // unknown bone
  EXPECT_FALSE(parse_amc("root 0 0 0 0 0 0\n", asf.skeleton).ok);            // before a frame number
  EXPECT_FALSE(parse_amc("1\nroot 0 0 0 0 0 x\n", asf.skeleton).ok);
  EXPECT_FALSE(parse_amc("", asf.skeleton).ok);
  std::string bad = kAsf;
  bad.replace(bad.find("lfemur ltibia"), 13, "lfemur shin");
  const auto r = parse_asf(bad);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("shin"), std::string::npos) << r.error;
}

TEST(AsfAmcParser, RealSubject16Loads) {
  const std::string dir = std::string(MATCHCAST_MOCAP_DIR) + "/asfamc/";
  MocapClip clip;
  std::string error;
  ASSERT_TRUE(io::load_amc(dir + "16.asf", dir + "16_15.amc", clip, error)) << error;
  EXPECT_EQ(clip.frames, 471);
  // Head tops reach 1.62-1.66 m (README of the data); the sole is ~2-5 cm up.
  float top = 0;
  std::vector<glm::vec3> p;
  for (int f = 0; f < clip.frames; f += 10) {
    forward_kinematics(clip, f, p);
    top = std::max(top, p[static_cast<std::size_t>(clip.skeleton.find("Head_end"))].y);
  }
  EXPECT_GT(top, 1.55f);
  EXPECT_LT(top, 1.75f);
}
