#include "anim/swing_clearance.hpp"

#include <array>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "anim/ground_contact.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/leg_pose_job.hpp"
#include "anim/local_to_model_job.hpp"
#include "proto/pose_frame.hpp"

namespace mc::anim {
namespace {

// The right sole's lowest corner, the legs solved for `job`'s targets.
float solved_sole(LegPoseJob& job, std::array<float, kMaxDof>& a) {
  job.angles = std::span<float>(a.data(), a.size());
  EXPECT_TRUE(job.Run());
  std::vector<glm::mat4> m(human_skeleton().joints.size());
  LocalToModelJob fk{&human_skeleton(), a, glm::vec3(0, job.pelvis_height, 0), m};
  EXPECT_TRUE(fk.Run());
  return segment_lowest_ms(human_skeleton().joints[kRFoot].segment, m[kRFoot]);
}

TEST(SwingClearance, ALiftedLegPutsItsSoleAtTheClearance) {
  // A leg swinging through, its ankle at heights and its sole at pitches a
  // run gives it; the other foot under its hip. The clearance asked of a
  // slow swing and of a sprinter's.
  int lifted_before = 0;
  for (const float clear : {kSwingClearM, 0.15f}) {
    int lifted = 0;
    for (float h : {0.06f, 0.09f, 0.12f, 0.16f})
      for (float pitch : {-40.0f, -20.0f, 0.0f, 15.0f, 30.0f}) {
        SCOPED_TRACE(testing::Message() << "clearance " << clear << " m, ankle " << h << " m, pitch " << pitch);
        std::array<float, kMaxDof> a{};
        LegPoseJob job;
        job.pelvis_height = 0.93f;
        job.feet[0].ankle_ms[0] = 0.15f; job.feet[0].ankle_ms[1] = h; job.feet[0].ankle_ms[2] = 0.11f;
        job.feet[0].pitch_deg = pitch;
        job.feet[1].ankle_ms[1] = 0.08f; job.feet[1].ankle_ms[2] = -0.11f;
        const float before = solved_sole(job, a);
        const float up = swing_lift(h, pitch, clear);
        EXPECT_GE(up, 0.0f);
        job.feet[0].ankle_ms[1] += up;
        const float after = solved_sole(job, a);
        if (up > 0) {
          ++lifted;
          EXPECT_LT(before, clear - 1e-3f);
          EXPECT_GE(after, clear - 1e-3f);
          // The sole asked for is the sole posed, unless the ankle could not
          // bend as far (toes up, the knee bent): then the toes are higher.
          if (job.ankle_pitch_deg[0] >= -60.0f && job.ankle_pitch_deg[0] <= 35.0f) {
            EXPECT_NEAR(after, clear, 1e-3f);
          }
        } else {
          EXPECT_GE(before, clear - 1e-3f);  // a foot left alone was clear already
        }
      }
    // Some feet are lifted and, at the slow swing's clearance, some are
    // clear already; a higher clearance lifts more of them.
    EXPECT_GT(lifted, 5);
    if (clear == kSwingClearM) {
      EXPECT_LT(lifted, 20);
    }
    EXPECT_GT(lifted, lifted_before);
    lifted_before = lifted;
  }
}

TEST(SwingClearance, AFootThatTravelsFurtherKeepsHigherWhileTheBodyRunsWithIt) {
  // A foot that barely moves is not looked at; a slow swing keeps the floor.
  EXPECT_EQ(swing_clear(kSkimStepM, 1.0f), 0.0f);
  EXPECT_FLOAT_EQ(swing_clear(0.10f, 0.05f), kSwingClearM);
  // A sprinter's swing (0.5 m a frame at 9 m/s, the body 0.45 m): higher
  // than a jog's (0.25 m, the body 0.15 m), within the ceiling.
  const float jog = swing_clear(0.25f, 0.15f), sprint = swing_clear(0.5f, 0.45f);
  EXPECT_GT(jog, kSwingClearM);
  EXPECT_GT(sprint, jog + 0.05f);
  EXPECT_LE(sprint, kSwingClearMaxM);
  EXPECT_FLOAT_EQ(swing_clear(3.0f, 3.0f), kSwingClearMaxM);
  // A player who stops: the body hardly moves while the last swing still
  // travels. It keeps the slow swing's floor, or the body floats.
  EXPECT_FLOAT_EQ(swing_clear(0.5f, 0.02f), kSwingClearM);
  EXPECT_LT(swing_clear(0.5f, 0.1f), sprint);
  // Never lower for a foot that travels further.
  for (float root : {0.0f, 0.1f, 0.3f})
    for (float d = 0.06f; d < 1.0f; d += 0.01f) EXPECT_GE(swing_clear(d + 0.01f, root), swing_clear(d, root));
}

TEST(SwingClearance, OnlyAFootThatTravelsLowIsLookedAt) {
  EXPECT_FALSE(may_skim(0.08f, kSkimStepM, kSwingClearM));      // a foot that barely moves
  EXPECT_TRUE(may_skim(0.08f, 2 * kSkimStepM, kSwingClearM));   // low and on its way
  EXPECT_FALSE(may_skim(0.40f, 2 * kSkimStepM, kSwingClearM));  // high in its swing
  EXPECT_TRUE(may_skim(0.30f, 0.6f, kSwingClearMaxM));          // a sprinter's, asked higher
  // Whatever way the foot is turned, an ankle may_skim leaves alone has its
  // sole clear: the lowest corner of the box over a sweep of orientations.
  const Segment& box = human_skeleton().joints[kRFoot].segment;
  for (const float clear : {kSwingClearM, kSwingClearMaxM}) {
    for (float h = 0.0f; h < 0.5f; h += 0.01f) {
      if (may_skim(h, 1.0f, clear)) continue;
      float lowest = 1.0f;
      for (float p = -180.0f; p < 180.0f; p += 15.0f)
        for (float r = -90.0f; r <= 90.0f; r += 15.0f) {
          glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(0, h, 0));
          m = glm::rotate(m, glm::radians(p), glm::vec3(0, 0, 1));
          m = glm::rotate(m, glm::radians(r), glm::vec3(1, 0, 0));
          lowest = std::min(lowest, segment_lowest_ms(box, m));
        }
      EXPECT_GE(lowest, clear) << "ankle " << h << ", clearance " << clear;
    }
  }
}

}  // namespace
}  // namespace mc::anim
