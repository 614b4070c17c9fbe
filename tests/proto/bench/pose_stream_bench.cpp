// Pose-stream benchmark (issue 5 "Targets"): encodes every frame of a real
// full game and prints bytes per frame for keyframes and deltas, kbit/s at
// 20 Hz, the largest errors after decoding, encode and decode time per
// frame, beside the same frames as JSON and as raw float32.
//
//   proto_pose_stream_bench [--log PATH] [--states N] [--keyframe-interval F] [--synth]
//                           [--save-frames PATH | --load-frames PATH]
//                           [--recording-keyframe-interval N]   (0: store the stream's frames)
//                           [--save-contacts PATH]
// --save/--load-frames keep the animated frames (and skeleton) in a file, so
// that codec variants are compared on identical input while anim changes.
// --save-contacts writes which feet the animator held planted (the frame
// count as 8 bytes, then kMaxPlayers bytes a frame: bit 0 right, bit 1
// left), for proto_pose_stream_stats --contacts.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <random>

#include "proto/frame_codec.hpp"
#include "proto/hello.hpp"
#include "server/record/recording_reader.hpp"
#include "server/record/recording_writer.hpp"
#include "tests/proto/support/real_game.hpp"

using namespace mc;
using namespace mc::proto;
using Clock = std::chrono::steady_clock;

namespace {

std::string as_json(const PoseFrame& f, int dofs) {
  nlohmann::json players = nlohmann::json::array();
  for (const auto& p : f.players) {
    std::vector<float> a(p.angles.begin(), p.angles.begin() + dofs);
    players.push_back({{"side", static_cast<int>(p.side)}, {"unum", p.unum}, {"state", p.state}, {"x", p.x},
                       {"y", p.y}, {"z", p.z}, {"heading", p.heading}, {"angles", a}});
  }
  return nlohmann::json{{"seq", f.seq}, {"time", f.time}, {"stoppage", f.stoppage}, {"substep", f.substep},
                        {"server_time_ms", f.server_time_ms}, {"play_mode", static_cast<int>(f.play_mode)},
                        {"score", {f.score_left, f.score_right}},
                        {"ball", {f.ball.x, f.ball.y, f.ball.z}}, {"players", players}}
      .dump();
}

double angle_diff(double a, double b) {
  double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360.0 - d);
}

}  // namespace

int main(int argc, char** argv) {
  std::string log = testing::default_full_game_log();
  std::size_t max_states = 0;
  EncoderOptions options;
  bool synth = false;
  std::string save_frames, load_frames, save_contacts;
  int recording_keyframe_interval = record::WriterOptions{}.keyframe_interval;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--log" && i + 1 < argc) log = argv[++i];
    else if (a == "--states" && i + 1 < argc) max_states = std::stoul(argv[++i]);
    else if (a == "--keyframe-interval" && i + 1 < argc) options.keyframe_interval = std::stoi(argv[++i]);
    else if (a == "--synth") synth = true;
    else if (a == "--recording-keyframe-interval" && i + 1 < argc) recording_keyframe_interval = std::stoi(argv[++i]);
    else if (a == "--save-frames" && i + 1 < argc) save_frames = argv[++i];
    else if (a == "--load-frames" && i + 1 < argc) load_frames = argv[++i];
    else if (a == "--save-contacts" && i + 1 < argc) save_contacts = argv[++i];
    else {
      std::fprintf(stderr,
                   "usage: %s [--log PATH] [--states N] [--keyframe-interval F] [--synth]\n"
                   "       [--save-frames PATH | --load-frames PATH] [--recording-keyframe-interval N]\n"
                   "       [--save-contacts PATH]\n",
                   argv[0]);
      return 2;
    }
  }
  testing::RealGame game;
  std::string error;
  const auto t_load = Clock::now();
  if (!load_frames.empty()) {
    std::FILE* in = std::fopen(load_frames.c_str(), "rb");
    std::uint64_t n = 0, len = 0;
    if (!in || std::fread(&len, 8, 1, in) != 1) return 1;
    std::string hello_text(len, '\0');
    if (std::fread(hello_text.data(), 1, len, in) != len || std::fread(&n, 8, 1, in) != 1) return 1;
    Hello h;
    if (!hello_from_json(hello_text, h, error)) return 1;
    game.skeleton = h.skeleton;
    game.animated_by = "frames from " + load_frames;
    game.frames.resize(n);
    if (std::fread(game.frames.data(), sizeof(PoseFrame), n, in) != n) return 1;
    std::fclose(in);
  } else if (!testing::load_real_game(log, !synth, max_states, game, error)) {
    std::fprintf(stderr, "cannot load %s: %s\n", log.c_str(), error.c_str());
    return 1;
  }
  if (!save_frames.empty()) {
    Hello h;
    h.skeleton = game.skeleton;
    const std::string hello_text = to_json(h);
    const std::uint64_t len = hello_text.size(), n = game.frames.size();
    std::FILE* out = std::fopen(save_frames.c_str(), "wb");
    if (!out) return 1;
    std::fwrite(&len, 8, 1, out);
    std::fwrite(hello_text.data(), 1, len, out);
    std::fwrite(&n, 8, 1, out);
    std::fwrite(game.frames.data(), sizeof(PoseFrame), n, out);
    std::fclose(out);
  }
  if (!save_contacts.empty()) {
    if (game.contacts.size() != game.frames.size() * kMaxPlayers) {
      std::fprintf(stderr, "--save-contacts: no foot contacts (only from anim::Animator, not --load-frames)\n");
      return 1;
    }
    const std::uint64_t n = game.frames.size();
    std::FILE* out = std::fopen(save_contacts.c_str(), "wb");
    if (!out) return 1;
    std::fwrite(&n, 8, 1, out);
    std::fwrite(game.contacts.data(), 1, game.contacts.size(), out);
    std::fclose(out);
  }
  const double load_s = std::chrono::duration<double>(Clock::now() - t_load).count();
  const int dofs = game.skeleton.dof_count();
  const auto& frames = game.frames;
  std::printf("log: %s\n", log.c_str());
  std::printf("frames: %zu (%s, skeleton '%s', %d dof, %.1f s to read and animate)\n", frames.size(),
              game.animated_by.c_str(), game.skeleton.name.c_str(), dofs, load_s);
  std::printf("keyframe interval: %d frames\n\n", options.keyframe_interval);

  FrameEncoder enc(game.skeleton, options);
  std::vector<std::string> encoded;
  std::vector<bool> is_key;
  encoded.reserve(frames.size());
  const auto t0 = Clock::now();
  for (const auto& f : frames) {
    bool key = false;
    encoded.push_back(enc.encode(f, key));
    is_key.push_back(key);
  }
  const double enc_s = std::chrono::duration<double>(Clock::now() - t0).count();

  FrameDecoder dec(game.skeleton);
  std::vector<PoseFrame> decoded(frames.size());
  const auto t1 = Clock::now();
  for (std::size_t i = 0; i < encoded.size(); ++i) {
    if (!dec.decode(encoded[i], decoded[i], error)) {
      std::fprintf(stderr, "decode failed at frame %zu: %s\n", i, error.c_str());
      return 1;
    }
  }
  const double dec_s = std::chrono::duration<double>(Clock::now() - t1).count();

  double max_angle = 0, max_heading = 0, max_pos = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto& a = frames[i];
    const auto& b = decoded[i];
    const auto dist = [](float ax, float ay, float az, float bx, float by, float bz) {
      return std::sqrt(double(ax - bx) * (ax - bx) + double(ay - by) * (ay - by) + double(az - bz) * (az - bz));
    };
    max_pos = std::max(max_pos, dist(a.ball.x, a.ball.y, a.ball.z, b.ball.x, b.ball.y, b.ball.z));
    for (std::size_t p = 0; p < a.players.size(); ++p) {
      const auto& pa = a.players[p];
      const auto& pb = b.players[p];
      max_pos = std::max(max_pos, dist(pa.x, pa.y, pa.z, pb.x, pb.y, pb.z));
      max_heading = std::max(max_heading, angle_diff(pa.heading, pb.heading));
      for (int d = 0; d < dofs; ++d)
        max_angle = std::max(max_angle, std::abs(double(pa.angles[static_cast<std::size_t>(d)]) - pb.angles[static_cast<std::size_t>(d)]));
    }
  }

  std::size_t key_n = 0, key_b = 0, delta_n = 0, delta_b = 0, key_max = 0, delta_max = 0;
  for (std::size_t i = 0; i < encoded.size(); ++i) {
    if (is_key[i]) key_n++, key_b += encoded[i].size(), key_max = std::max(key_max, encoded[i].size());
    else delta_n++, delta_b += encoded[i].size(), delta_max = std::max(delta_max, encoded[i].size());
  }
  std::size_t json_b = 0;
  for (const auto& f : frames) json_b += as_json(f, dofs).size();
  const double raw_frame = kFrameHeaderSize + 4.0 * (3 + kMaxPlayers * (4 + dofs)) + kMaxPlayers * 6;  // + ids/state
  const double n = static_cast<double>(frames.size());
  const double mean = static_cast<double>(key_b + delta_b) / n;
  const auto kbps = [](double bytes_per_frame) { return bytes_per_frame * 8 * 20 / 1000; };

  std::printf("%-24s %12s %12s %12s\n", "encoding", "B/frame", "kbit/s@20Hz", "vs codec");
  std::printf("%-24s %12.1f %12.1f %11.1fx\n", "codec (mean)", mean, kbps(mean), 1.0);
  std::printf("%-24s %12.1f %12s   (%zu keyframes, largest %zu B)\n", "  keyframes", double(key_b) / double(key_n), "",
              key_n, key_max);
  std::printf("%-24s %12.1f %12s   (%zu deltas, largest %zu B)\n", "  deltas", delta_n ? double(delta_b) / double(delta_n) : 0.0,
              "", delta_n, delta_max);
  std::printf("%-24s %12.1f %12.1f %11.1fx\n", "raw float32", raw_frame, kbps(raw_frame), raw_frame / mean);
  std::printf("%-24s %12.1f %12.1f %11.1fx\n", "JSON", double(json_b) / n, kbps(double(json_b) / n),
              double(json_b) / n / mean);
  std::printf("\nfull game: %.2f MB of frames (%.0f s of play)\n", double(key_b + delta_b) / 1e6, n / 20.0);
  std::printf("largest joint-angle error: %.3f deg (budget 0.5)\n", max_angle);
  std::printf("largest heading error:     %.3f deg (budget 0.5)\n", max_heading);
  std::printf("largest position error:    %.2f cm (3D distance, budget 1)\n", max_pos * 100);
  std::printf("encode: %.1f us/frame   decode: %.1f us/frame\n", enc_s * 1e6 / n, dec_s * 1e6 / n);

  // The recording of the same frames, written to a temporary file, and
  // seeks to random simulation times through the reader.
  Hello hello;
  hello.skeleton = game.skeleton;
  hello.keyframe_interval = options.keyframe_interval;
  hello.left.name = game.left_name;
  hello.right.name = game.right_name;
  const std::string path = "/tmp/matchcast-bench-" + std::to_string(::getpid()) + ".mcrec";
  {
    record::RecordingWriter w;
    record::WriterOptions wo;
    wo.sync = false;
    wo.keyframe_interval = recording_keyframe_interval;
    if (!w.open(path, to_json(hello), error, wo)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    // With the control messages the server records (stamina, kicks, play
    // modes): the file is what matchcast-server writes for this game.
    testing::for_each_in_stream_order(
        game, [&](std::size_t i) { w.add_frame(encoded[i], error); },
        [&](const std::string& text) { w.add_control(text, error); });
    w.close(error);
  }
  record::RecordingReader reader;
  if (!reader.open(path, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  std::FILE* fp = std::fopen(path.c_str(), "rb");
  std::fseek(fp, 0, SEEK_END);
  const long rec_size = std::ftell(fp);
  std::fclose(fp);
  std::mt19937 rng(1);
  const int last_time = frames.back().time;
  double seek_max = 0, seek_sum = 0;
  const int seeks = 200;
  for (int i = 0; i < seeks; ++i) {
    const int t = static_cast<int>(rng() % static_cast<unsigned>(last_time));
    PoseFrame f;
    const auto s0 = Clock::now();
    if (!reader.seek(t, f, error)) {
      std::fprintf(stderr, "seek %d failed: %s\n", t, error.c_str());
      return 1;
    }
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - s0).count();
    seek_max = std::max(seek_max, ms);
    seek_sum += ms;
  }
  std::remove(path.c_str());
  std::printf("recording: %.3f MB for the full game (target 3 MB), %zu chunks, %zu control messages, %s\n",
              rec_size / 1e6, reader.chunks().size(), game.controls.size(),
              recording_keyframe_interval > 0
                  ? ("transcoded to a keyframe every " + std::to_string(recording_keyframe_interval) + " frames").c_str()
                  : "the stream's frames as sent");
  std::printf("seek to a random time: mean %.2f ms, max %.2f ms over %d seeks (target 10 ms)\n", seek_sum / seeks,
              seek_max, seeks);

  const bool ok = mean <= 300 && max_angle <= 0.5 && max_heading <= 0.5 && max_pos <= 0.01;
  std::printf("\nstream targets (mean <= 300 B, angle <= 0.5 deg, position <= 1 cm): %s\n", ok ? "MET" : "NOT MET");
  std::printf("recording targets (<= 3 MB, seek <= 10 ms): %s\n", rec_size <= 3000000 && seek_max <= 10 ? "MET" : "NOT MET");
  return 0;
}
