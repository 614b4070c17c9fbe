// matchcast-log-frames LOG OUT [--base MS] [--keyframe-interval N]
//                              [--lookahead N] [--detail none|run|kick|full] [--match-id ID]
//
// Runs the server's pipeline on a log (any version, gzip or plain: the
// server's own reader, ingest::open_log) and writes what it makes in the
// WebAssembly module's output format (wasm/log_session.hpp): the hello,
// then each control message and frame in wire order. Frame n is stamped
// BASE + 50 n ms, as the module does. tests/web/wasm_frames.test.mjs
// compares the module's output with this file, byte for byte.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "wasm/log_reference.hpp"

namespace {

int usage() {
  std::fprintf(stderr,
               "usage: matchcast-log-frames LOG OUT [--base MS] [--keyframe-interval N] [--lookahead N]\n"
               "                            [--detail none|run|kick|full] [--match-id ID]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage();
  const std::string log = argv[1], out_path = argv[2];
  mc::wasm::LogSessionOptions options;
  options.match_id = log;
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--base") options.server_time_base_ms = std::strtoull(v.c_str(), nullptr, 10);
    else if (k == "--keyframe-interval") options.pipeline.keyframe_interval = std::atoi(v.c_str());
    else if (k == "--lookahead") options.pipeline.anim.lookahead_cycles = std::atoi(v.c_str());
    else if (k == "--match-id") options.match_id = v;
    else if (k == "--detail") {
      auto d = mc::anim::detail_from_name(v);
      if (!d) return usage();
      options.pipeline.anim.detail = *d;
    } else {
      return usage();
    }
  }
  const auto t0 = std::chrono::steady_clock::now();
  std::string out, error;
  if (!mc::wasm::broadcast_log_file(log, options, out, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::ofstream f(out_path, std::ios::binary);
  f.write(out.data(), static_cast<std::streamsize>(out.size()));
  if (!f) {
    std::fprintf(stderr, "%s: cannot write\n", out_path.c_str());
    return 1;
  }
  std::printf("%zu bytes in %.0f ms\n", out.size(), ms);
  return 0;
}
