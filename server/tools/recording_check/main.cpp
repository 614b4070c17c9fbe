// matchcast-recording-check FILE...: reads each recording from end to end
// with the reader the relay's replay and the viewer use, and prints one
// line per file: frames, time range, whether it was closed with its index,
// bytes ignored at its end, frames skipped. Exit 1 when a file cannot be
// opened or has damaged data before its end (scripts/soak.sh uses it).
#include <cstdio>
#include <string>

#include "server/record/recording_reader.hpp"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: matchcast-recording-check FILE...\n");
    return 2;
  }
  int bad = 0;
  for (int i = 1; i < argc; ++i) {
    mc::record::RecordingReader reader;
    std::string error;
    if (!reader.open(argv[i], error)) {
      std::printf("%s: CANNOT OPEN: %s\n", argv[i], error.c_str());
      ++bad;
      continue;
    }
    mc::PoseFrame f;
    std::uint64_t frames = 0, controls = 0;
    int first = -1, last = -1;
    std::uint32_t first_seq = 0, last_seq = 0;
    std::vector<std::string> texts;
    while (reader.next(f, error, &texts)) {
      if (frames == 0) {
        first = f.time;
        first_seq = f.seq;
      }
      last = f.time;
      last_seq = f.seq;
      ++frames;
    }
    controls = texts.size();
    const bool ok = error.empty() && frames > 0;
    std::printf("%s: %s frames %llu (seq %u-%u), cycles %d-%d, controls %llu, %s, tail ignored %llu B, skipped %llu%s%s\n",
                argv[i], ok ? "ok" : "BAD", static_cast<unsigned long long>(frames), first_seq, last_seq, first, last,
                static_cast<unsigned long long>(controls), reader.recovered() ? "no index (recovered)" : "indexed",
                static_cast<unsigned long long>(reader.ignored_tail_bytes()),
                static_cast<unsigned long long>(reader.skipped_frames()), error.empty() ? "" : ": ", error.c_str());
    if (!ok) ++bad;
  }
  return bad ? 1 : 0;
}
