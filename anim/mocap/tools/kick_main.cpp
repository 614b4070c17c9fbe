// matchcast-mocap-kick: a picture of the CMU kicks retargeted onto the
// broadcast skeleton (anim/mocap/retarget_job.hpp), seen from the side: one
// row per kick clip, 9 poses from 0.3 s before ball contact to 0.3 s after
// (contact in the middle cell); the last row bends 10_05's kick by IK so the
// ankle meets a ball 15 cm further ahead and 5 cm further right at contact.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "anim/human_skeleton.hpp"
#include "anim/local_to_model_job.hpp"
#include "anim/mocap/io/clip_files.hpp"
#include "anim/mocap/retarget_job.hpp"
#include "anim/tools/strip_plot.hpp"

using namespace mc::anim::mocap;
namespace tools = mc::anim::tools;

int main(int argc, char** argv) {
  std::string data = MATCHCAST_DEFAULT_MOCAP_DIR, out = "mocap-kicks.png";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--data" && i + 1 < argc) data = argv[++i];
    else if (a == "--png" && i + 1 < argc) out = argv[++i];
    else { std::fprintf(stderr, "usage: %s [--data DIR] [--png FILE]\n", argv[0]); return 2; }
  }
  const std::vector<std::string> clips = {"cmu_10_01.bvh", "cmu_10_02.bvh", "cmu_10_03.bvh", "cmu_10_05.bvh", "cmu_10_06.bvh"};
  const int cells = 9;
  tools::Image img(cells * tools::kCellPx, static_cast<int>(clips.size() + 1) * tools::kRowPx);
  const auto& skel = mc::anim::human_skeleton();
  int row = 0;
  bool ok = true;
  for (std::size_t r = 0; r <= clips.size(); ++r) {
    const bool bent = r == clips.size();
    const std::string name = bent ? "cmu_10_05.bvh" : clips[r];
    MocapClip raw;
    std::string error;
    if (!io::load_bvh(data + "/" + name, raw, error)) { std::fprintf(stderr, "%s\n", error.c_str()); return 1; }
    const MocapClip clip = resample(raw, 30);
    const int contact = kick_contact_frame(clip, true);
    std::vector<mc::PoseFrame> frames(cells);
    std::vector<const mc::PoseFrame*> ptrs;
    int reached = 0;
    for (int c = 0; c < cells; ++c) {
      const float f = static_cast<float>(contact) + static_cast<float>(c - cells / 2) * 9.0f / static_cast<float>(cells / 2);
      auto& pose = frames[static_cast<std::size_t>(c)].players[0];
      pose.side = mc::Side::Left;
      pose.unum = 9;
      MocapRetargetJob job;
      job.clip = &clip;
      job.frame = std::clamp(f, 0.0f, static_cast<float>(clip.frames - 1));
      job.angles = std::span<float>(pose.angles.data(), static_cast<std::size_t>(mc::anim::dof::kCount));
      job.pelvis_height = &pose.z;
      if (bent) {
        // The plain retarget's ankle at contact, moved 15 cm ahead and 5 cm right.
        mc::PlayerPose plain_pose;
        MocapRetargetJob plain = job;
        plain.frame = static_cast<float>(contact);
        plain.angles = std::span<float>(plain_pose.angles.data(), static_cast<std::size_t>(mc::anim::dof::kCount));
        plain.pelvis_height = &plain_pose.z;
        plain.Run();
        std::vector<glm::mat4> pm(skel.joints.size());
        mc::anim::LocalToModelJob pfk;
        pfk.skeleton = &skel;
        pfk.angles_deg = std::span<const float>(plain_pose.angles.data(), static_cast<std::size_t>(mc::anim::dof::kCount));
        pfk.root_ms = glm::vec3(0, plain_pose.z, 0);
        pfk.models = pm;
        pfk.Run();
        const glm::vec3 pa = pm[mc::anim::kRFoot][3];
        job.kick_foot = 0;
        job.contact_frame = static_cast<float>(contact);
        job.ankle_target[0] = pa.x + 0.15f;
        job.ankle_target[1] = pa.y;
        job.ankle_target[2] = pa.z + 0.05f;
      }
      if (!job.Run()) { std::fprintf(stderr, "%s: retarget refused at frame %.1f\n", name.c_str(), static_cast<double>(f)); ok = false; }
      reached += job.reached ? 1 : 0;
      if (bent && c == cells / 2) {
        std::vector<glm::mat4> m(skel.joints.size());
        mc::anim::LocalToModelJob fk;
        fk.skeleton = &skel;
        fk.angles_deg = std::span<const float>(pose.angles.data(), static_cast<std::size_t>(mc::anim::dof::kCount));
        fk.root_ms = glm::vec3(0, pose.z, 0);
        fk.models = m;
        fk.Run();
        const glm::vec3 a = m[mc::anim::kRFoot][3];
        std::printf("bent kick: right ankle at contact (%.3f, %.3f, %.3f) m, target (%.2f, %.2f, %.2f)\n",
                    static_cast<double>(a.x), static_cast<double>(a.y), static_cast<double>(a.z),
                    static_cast<double>(job.ankle_target[0]), static_cast<double>(job.ankle_target[1]),
                    static_cast<double>(job.ankle_target[2]));
      }
      ptrs.push_back(&frames[static_cast<std::size_t>(c)]);
    }
    std::printf("%s%s: contact at frame %d (%.2f s), %d of %d poses with both ankles reached\n", name.c_str(),
                bent ? " (bent to a ball)" : "", contact, contact / 30.0, reached, cells);
    tools::draw_pose_row(img, row++, skel, ptrs, 0, 0.0f);
  }
  std::string err;
  if (!tools::write_png(out, img, err)) { std::fprintf(stderr, "%s\n", err.c_str()); return 1; }
  std::printf("wrote %s\n", out.c_str());
  return ok ? 0 : 1;
}
