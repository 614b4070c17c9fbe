#include "anim/mocap/io/clip_files.hpp"

#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "anim/mocap/asf_amc_parser.hpp"
#include "anim/mocap/bvh_parser.hpp"
#include "anim/mocap/mocap_blob.hpp"

namespace mc::anim::mocap::io {

namespace {

bool exists(const std::string& path) {
  struct stat st{};
  return ::stat(path.c_str(), &st) == 0;
}

}  // namespace

// The clips ship gzipped (data/mocap/*.gz): a name without ".gz" that is not
// on disk is read from its ".gz" twin. zlib's gzread passes a file that is
// not gzip through unchanged, so one path reads both.
bool read_file(const std::string& path, std::string& out, std::string& error) {
  const std::string actual = (!exists(path) && exists(path + ".gz")) ? path + ".gz" : path;
  gzFile in = ::gzopen(actual.c_str(), "rb");
  if (in == nullptr) { error = path + ": cannot open"; return false; }
  std::string bytes;
  char buffer[1 << 16];
  int n = 0;
  while ((n = ::gzread(in, buffer, sizeof buffer)) > 0) bytes.append(buffer, static_cast<std::size_t>(n));
  int zerr = Z_OK;
  const char* message = ::gzerror(in, &zerr);
  const bool truncated = n < 0 || (zerr != Z_OK && zerr != Z_BUF_ERROR);
  ::gzclose(in);
  if (truncated) { error = actual + ": read error (" + message + ")"; return false; }
  out = std::move(bytes);
  return true;
}

bool write_file(const std::string& path, const std::string& bytes, std::string& error) {
  // A private temporary name: tests running at once may write the same cache.
  const std::string tmp = path + "." + std::to_string(::getpid()) + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) { error = tmp + ": cannot create"; return false; }
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) { error = tmp + ": write error"; return false; }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) { error = path + ": cannot rename"; return false; }
  return true;
}

bool load_bvh(const std::string& path, MocapClip& clip, std::string& error) {
  std::string text;
  if (!read_file(path, text, error)) return false;
  auto r = parse_bvh(text);
  if (!r.ok) { error = path + ":" + r.error; return false; }
  clip = std::move(r.clip);
  const auto slash = path.find_last_of('/');
  clip.name = path.substr(slash == std::string::npos ? 0 : slash + 1);
  return true;
}

bool load_amc(const std::string& asf_path, const std::string& amc_path, MocapClip& clip, std::string& error) {
  std::string asf_text, amc_text;
  if (!read_file(asf_path, asf_text, error) || !read_file(amc_path, amc_text, error)) return false;
  auto asf = parse_asf(asf_text);
  if (!asf.ok) { error = asf_path + ":" + asf.error; return false; }
  auto amc = parse_amc(amc_text, asf.skeleton);
  if (!amc.ok) { error = amc_path + ":" + amc.error; return false; }
  clip = std::move(amc.clip);
  const auto slash = amc_path.find_last_of('/');
  clip.name = amc_path.substr(slash == std::string::npos ? 0 : slash + 1);
  return true;
}

bool load_cmu_clip_set(const ClipSetOptions& o, std::vector<MocapClip>& clips, std::uint64_t& hash,
                       std::string& error) {
  clips.clear();
  hash = fnv1a64("mocap-clip-set-v1");
  std::vector<std::string> bvh = {"cmu_10_04.bvh", "cmu_10_01.bvh", "cmu_10_02.bvh", "cmu_10_03.bvh",
                                  "cmu_10_05.bvh", "cmu_10_06.bvh"};
  if (o.include_jumps) bvh.push_back("cmu_01_01.bvh");
  std::vector<std::string> amc;
  if (o.include_asf)
    for (const char* t : {"12", "13", "14", "15", "16", "17", "18", "24", "26", "29"}) amc.push_back(std::string("16_") + t + ".amc");
  std::vector<MocapClip> raw;
  for (const auto& f : bvh) {
    std::string text;
    if (!read_file(o.dir + "/" + f, text, error)) return false;
    hash = fnv1a64(text, hash);
    auto r = parse_bvh(text);
    if (!r.ok) { error = o.dir + "/" + f + ":" + r.error; return false; }
    r.clip.name = f;
    raw.push_back(std::move(r.clip));
  }
  if (!amc.empty()) {
    std::string asf_text;
    const std::string asf_path = o.dir + "/asfamc/16.asf";
    if (!read_file(asf_path, asf_text, error)) return false;
    hash = fnv1a64(asf_text, hash);
    const auto asf = parse_asf(asf_text);
    if (!asf.ok) { error = asf_path + ":" + asf.error; return false; }
    for (const auto& f : amc) {
      std::string text;
      const std::string path = o.dir + "/asfamc/" + f;
      if (!read_file(path, text, error)) return false;
      hash = fnv1a64(text, hash);
      auto r = parse_amc(text, asf.skeleton);
      if (!r.ok) { error = path + ":" + r.error; return false; }
      r.clip.name = f;
      raw.push_back(std::move(r.clip));
    }
  }
  // Subject 10's walk defines the canonical offsets.
  const MocapSkeleton canonical = raw.front().skeleton;
  for (auto& c : raw) {
    retarget_offsets(c, canonical);
    MocapClip s = resample(c, o.hz);
    if (o.max_frames_per_clip > 0 && s.frames > o.max_frames_per_clip) {
      s.frames = o.max_frames_per_clip;
      s.root_position.resize(static_cast<std::size_t>(s.frames));
      s.local.resize(static_cast<std::size_t>(s.frames) * s.skeleton.names.size());
    }
    clips.push_back(std::move(s));
  }
  hash = fnv1a64(std::to_string(o.hz) + "/" + std::to_string(o.max_frames_per_clip), hash);
  return true;
}

}  // namespace mc::anim::mocap::io
