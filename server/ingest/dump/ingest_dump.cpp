// matchcast-ingest-dump SOURCE [--every N] [--max N] [--quiet]
//
// Prints the state stream of a log or a live server, one line per state
// (index, time, stoppage, play mode, score, ball, active players), the
// events (messages, feed lost/back) in place, and the ingest statistics
// with the first errors at the end. SOURCE is a log path or udp://HOST:PORT.
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "server/ingest/state_source.hpp"

namespace {
mc::ingest::StateSource* g_source = nullptr;
extern "C" void on_signal(int) {
  if (g_source) g_source->stop();
}

const char* kind_name(mc::ingest::SourceEvent::Kind k) {
  using K = mc::ingest::SourceEvent::Kind;
  switch (k) {
    case K::Message: return "msg";
    case K::FeedLost: return "feed-lost";
    case K::FeedBack: return "feed-back";
    case K::ServerReply: return "reply";
  }
  return "?";
}
}  // namespace

int main(int argc, char** argv) {
  std::string spec;
  long every = 1, max = -1;
  bool quiet = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--every" && i + 1 < argc) every = std::max(1L, std::atol(argv[++i]));
    else if (a == "--max" && i + 1 < argc) max = std::atol(argv[++i]);
    else if (a == "--quiet") quiet = true;
    else if (a == "-h" || a == "--help") {
      std::printf("usage: matchcast-ingest-dump SOURCE [--every N] [--max N] [--quiet]\n"
                  "  SOURCE: a game log (.rcg[.gz], any version) or udp://HOST:PORT[/VERSION]\n");
      return 0;
    } else spec = a;
  }
  if (spec.empty()) {
    std::fprintf(stderr, "matchcast-ingest-dump: no SOURCE (try --help)\n");
    return 2;
  }
  std::string error;
  auto src = mc::ingest::open_source(spec, error);
  if (!src) {
    std::fprintf(stderr, "matchcast-ingest-dump: %s\n", error.c_str());
    return 1;
  }
  g_source = src.get();
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  mc::WorldState s;
  mc::ingest::SourceEvent ev;
  auto drain = [&] {
    while (src->poll_event(ev))
      if (!quiet)
        std::printf("  [%s before #%llu] %s%s\n", kind_name(ev.kind),
                    static_cast<unsigned long long>(ev.next_index), ev.message.text.c_str(), ev.detail.c_str());
  };
  long n = 0;
  for (;;) {
    const auto w = src->next_for(s, std::chrono::milliseconds(500));
    drain();
    if (w == mc::ingest::StateSource::Wait::End) break;
    if (w == mc::ingest::StateSource::Wait::Idle) continue;
    if (!quiet && s.index % static_cast<unsigned long>(every) == 0) {
      int active = 0;
      for (const auto& p : s.players) active += p.active();
      std::printf("#%llu t=%d+%d %s %s %d-%d %s ball=(%.2f,%.2f) active=%d\n",
                  static_cast<unsigned long long>(s.index), s.time, s.stoppage,
                  std::string(mc::play_mode_name(s.play_mode)).c_str(), s.left.name.c_str(), s.left.score,
                  s.right.score, s.right.name.c_str(), s.ball.x, s.ball.y, active);
    }
    if (max >= 0 && ++n >= max) break;
  }
  const auto& st = src->stats();
  std::printf("states %llu, skipped %llu, bytes %llu, player types %zu\n",
              static_cast<unsigned long long>(st.shows), static_cast<unsigned long long>(st.skipped),
              static_cast<unsigned long long>(st.bytes), src->params().player_types.size());
  for (const std::string& e : st.errors) std::printf("  error: %s\n", e.c_str());
  return 0;
}
