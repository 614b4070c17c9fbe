// matchcast-server: reads games, animates them and serves them to spectators.
#include <sys/resource.h>

#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "server/app/feed_control.hpp"
#include "server/app/log_feed.hpp"
#include "server/app/nats_roles.hpp"
#include "server/app/recordings.hpp"
#include "server/app/server_options.hpp"
#include "server/relay/log.hpp"
#include "server/relay/relay_server.hpp"
#include "server/replay/replay_catalog.hpp"

namespace {

// Every spectator is a file descriptor: use all the process may have.
void raise_fd_limit() {
  rlimit r{};
  if (getrlimit(RLIMIT_NOFILE, &r) == 0 && r.rlim_cur < r.rlim_max) {
    r.rlim_cur = r.rlim_max;
    setrlimit(RLIMIT_NOFILE, &r);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string message;
  int exit_code = 0;
  auto options = mc::app::parse_server_options(argc, argv, message, exit_code);
  if (!options) {
    std::fprintf(exit_code ? stderr : stdout, "%s\n", message.c_str());
    return exit_code;
  }
  raise_fd_limit();

  // Block the stop signals before any thread starts, so that every thread
  // inherits the mask and only sigwait() below sees them.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  std::signal(SIGPIPE, SIG_IGN);
  // Past a file-size limit (RLIMIT_FSIZE) a write fails with EFBIG, which
  // the recorder reports, instead of the default: the process killed.
  std::signal(SIGXFSZ, SIG_IGN);

  auto channels = std::make_shared<mc::relay::ChannelRegistry>();
  mc::app::FeedControl feeds(channels);
  std::string error;
  for (const auto& cf : options->feeds) {
    if (!feeds.add(cf.channel, cf.feed, error)) {
      std::fprintf(stderr, "matchcast-server: %s\n", error.c_str());
      return 1;
    }
  }
  // Before the recorders: each live recording is also its channel's time shift.
  mc::replay::ReplayCatalog replays(options->record_dir);
  // One file per game; the oldest deleted past --record-max-bytes/-age.
  mc::app::Recordings recordings(options->record_dir, options->retention, &replays);
  recordings.prune();
  auto record = [&](const std::shared_ptr<mc::relay::Channel>& channel) {
    // A recording that cannot start is logged; the broadcast goes on.
    recordings.record(channel);
  };
  // With NATS, exactly one place records (--record-at).
  if (mc::app::records_local_feeds(*options))
    for (const auto& cf : options->feeds) record(channels->find(cf.channel));
  mc::app::NatsRoles nats;
  if (!nats.start(*options, channels,
                  mc::app::records_edge_games(*options) ? mc::nats::EdgeRelay::ReadyHandler(record) : nullptr,
                  error)) {
    std::fprintf(stderr, "matchcast-server: %s\n", error.c_str());
    return 1;
  }
  mc::relay::RelayServer server(options->relay, channels, &feeds, &replays);
  if (!server.start(error)) {
    std::fprintf(stderr, "matchcast-server: %s\n", error.c_str());
    if (options->relay.port != 0 && error.rfind("cannot listen", 0) == 0)
      std::fprintf(stderr, "Is another program using port %u? Try --port 0 or --port N.\n",
                   options->relay.port);
    return 1;
  }
  const std::string host =
      options->relay.address == "0.0.0.0" ? "127.0.0.1" : options->relay.address;
  std::printf("Matchcast: open %s://%s:%u/\n", server.tls() ? "https" : "http", host.c_str(), server.port());
  std::fflush(stdout);
  mc::relay::log_event("listening", host + ":" + std::to_string(server.port()));

  // Until a stop signal: retention also applies to recordings that age
  // while nothing new is written.
  int sig = -1;
  const timespec prune_every{60, 0};
  while (sig <= 0) {
    sig = sigtimedwait(&stop_signals, nullptr, &prune_every);
    if (sig <= 0) recordings.prune();
  }
  mc::relay::log_event("stopping", sig == SIGTERM ? "SIGTERM" : "SIGINT");
  feeds.stop_all();
  nats.stop();
  server.stop();
  recordings.stop_all();
  mc::relay::log_event("stopped");
  return 0;
}
