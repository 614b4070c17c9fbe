// matchcast-ingest-bench [--repeat N] [LOG...]
//
// Throughput of the log reader on full games (default: both games in
// tests/data/rcg/full/). For each log it measures, best of N runs:
//   inflate  - gunzip only (ByteSource), MB/s of decompressed output;
//   stream   - open_log() on the .gz file end to end (inflate + parse);
//   text     - open_log() on a decompressed copy (a temp file, streamed):
//              the text parser alone, the figure behind the 300 MB/s target.
// Then peak RSS (getrusage ru_maxrss), which stays small because nothing is
// loaded whole.
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "server/ingest/byte_source.hpp"
#include "server/ingest/state_source.hpp"

#ifndef MATCHCAST_TEST_RCG_DIR
#define MATCHCAST_TEST_RCG_DIR "tests/data/rcg"
#endif

namespace {

using Clock = std::chrono::steady_clock;

// Wall time is what a user waits; CPU time of this thread is the per-core
// cost, which stays meaningful on a shared, loaded machine. Both are kept.
struct Run {
  double seconds = 1e300;   // CPU seconds (this thread)
  double wall = 1e300;      // wall-clock seconds
  std::uint64_t bytes = 0;  // decoded bytes
  std::uint64_t shows = 0;
};

double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

struct Timer {
  Clock::time_point wall0 = Clock::now();
  double cpu0 = cpu_now();
  void keep_best(Run& best, std::uint64_t bytes, std::uint64_t shows) const {
    const double cpu = cpu_now() - cpu0;
    const double wall = std::chrono::duration<double>(Clock::now() - wall0).count();
    if (cpu < best.seconds) {
      best.seconds = cpu;
      best.bytes = bytes;
      best.shows = shows;
    }
    if (wall < best.wall) best.wall = wall;
  }
};

long peak_rss_kib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;  // KiB on Linux
}

bool inflate_only(const std::string& path, Run& best) {
  std::string err;
  const Timer t;
  auto src = mc::ingest::open_file_source(path, err);
  if (!src) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return false;
  }
  std::vector<char> buf(1 << 20);
  std::uint64_t total = 0;
  while (std::size_t n = src->read(buf.data(), buf.size())) total += n;
  t.keep_best(best, total, 0);
  return true;
}

bool parse(const std::string& path, Run& best) {
  std::string err;
  const Timer t;
  auto src = mc::ingest::open_log(path, err);
  if (!src) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return false;
  }
  mc::WorldState s;
  mc::ingest::SourceEvent ev;
  while (src->next(s))
    while (src->poll_event(ev)) {
    }
  t.keep_best(best, src->stats().bytes, src->stats().shows);
  if (src->stats().skipped != 0)
    std::fprintf(stderr, "warning: %llu records skipped in %s\n",
                 static_cast<unsigned long long>(src->stats().skipped), path.c_str());
  return true;
}

// Writes the decoded bytes of `path` to a temp file; "" on failure.
std::string decompressed_copy(const std::string& path) {
  std::string err;
  auto src = mc::ingest::open_file_source(path, err);
  if (!src) return {};
  char name[] = "/tmp/matchcast-bench-XXXXXX";
  const int fd = mkstemp(name);
  if (fd < 0) return {};
  std::FILE* f = fdopen(fd, "wb");
  std::vector<char> buf(1 << 20);
  while (std::size_t n = src->read(buf.data(), buf.size())) std::fwrite(buf.data(), 1, n, f);
  std::fclose(f);
  return name;
}

void report(const char* what, const Run& r) {
  const double mb = static_cast<double>(r.bytes) / 1e6;
  std::printf("  %-8s %6.1f MB  cpu %6.3f s = %6.1f MB/s", what, mb, r.seconds, mb / r.seconds);
  if (r.shows) std::printf(", %6.0f shows/s", static_cast<double>(r.shows) / r.seconds);
  std::printf("  (wall %6.3f s = %6.1f MB/s)\n", r.wall, mb / r.wall);
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 3;
  std::vector<std::string> logs;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--repeat" && i + 1 < argc) repeat = std::max(1, std::atoi(argv[++i]));
    else if (a == "-h" || a == "--help") {
      std::printf("usage: matchcast-ingest-bench [--repeat N] [LOG...]\n");
      return 0;
    } else logs.push_back(a);
  }
  if (logs.empty()) {
    const std::string full = std::string(MATCHCAST_TEST_RCG_DIR) + "/full/";
    logs = {full + "20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz",
            full + "20261122031059-HELIOS_A_4-vs-HELIOS_B_3.rcg.gz"};
  }
  Run tot_inflate{0, 0, 0, 0}, tot_stream{0, 0, 0, 0}, tot_text{0, 0, 0, 0};
  auto add = [](Run& tot, const Run& r) {
    tot.seconds += r.seconds;
    tot.wall += r.wall;
    tot.bytes += r.bytes;
    tot.shows += r.shows;
  };
  // Streaming runs first, so the peak RSS printed after them is the
  // streaming reader's.
  std::vector<std::string> copies;
  for (const std::string& path : logs) {
    Run inflate, stream;
    for (int i = 0; i < repeat; ++i)
      if (!inflate_only(path, inflate) || !parse(path, stream)) return 1;
    std::printf("%s\n", path.c_str());
    report("inflate", inflate);
    report("stream", stream);
    add(tot_inflate, inflate);
    add(tot_stream, stream);
  }
  const long rss_stream = peak_rss_kib();
  for (const std::string& path : logs) {
    const std::string copy = decompressed_copy(path);
    if (copy.empty()) return 1;
    Run text;
    for (int i = 0; i < repeat; ++i)
      if (!parse(copy, text)) return 1;
    std::remove(copy.c_str());
    std::printf("%s (decompressed copy)\n", path.c_str());
    report("text", text);
    add(tot_text, text);
  }
  std::printf("total (%zu logs, best of %d):\n", logs.size(), repeat);
  report("inflate", tot_inflate);
  report("stream", tot_stream);
  report("text", tot_text);
  std::printf("peak RSS: %.1f MiB after streaming runs, %.1f MiB at exit\n", rss_stream / 1024.0,
              peak_rss_kib() / 1024.0);
  const double text_mbs = static_cast<double>(tot_text.bytes) / 1e6 / tot_text.seconds;
  std::printf("text parse target 300 MB/s on one core (CPU time): %s\n", text_mbs >= 300 ? "met" : "NOT met");
  return 0;
}
