// The file side of the mocap loaders (the parsers in anim/mocap take text in
// memory): reads BVH and ASF/AMC files, and the standard CMU clip set of
// data/mocap (gzipped) resampled to 30 Hz on one skeleton.
#pragma once

#include <string>
#include <vector>

#include "anim/mocap/mocap_clip.hpp"

namespace mc::anim::mocap::io {

// Whole file as bytes; false with `error` set when it cannot be read.
bool read_file(const std::string& path, std::string& out, std::string& error);
bool write_file(const std::string& path, const std::string& bytes, std::string& error);

// "path:row:col: message" on failure.
bool load_bvh(const std::string& path, MocapClip& clip, std::string& error);
bool load_amc(const std::string& asf_path, const std::string& amc_path, MocapClip& clip, std::string& error);

struct ClipSetOptions {
  std::string dir;            // data/mocap
  double hz = 30;             // resampling rate
  bool include_asf = true;    // subject 16's walks (ASF/AMC)
  bool include_jumps = true;  // cmu_01_01 (forward jumps, turn around)
  int max_frames_per_clip = 0;  // 0 = all; a cut for fast tests
};

// The clips of sets A and C (the Daz-friendly 11_01 has another skeleton and
// is left out), each retargeted to subject 10's offsets and resampled.
// `bytes_hash` receives a hash of every file read, for cache keys.
bool load_cmu_clip_set(const ClipSetOptions& options, std::vector<MocapClip>& clips,
                       std::uint64_t& bytes_hash, std::string& error);

}  // namespace mc::anim::mocap::io
