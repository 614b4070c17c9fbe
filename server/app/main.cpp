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
#include "server/app/recorder.hpp"
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

// <channel>-<UTC date-time>.mcrec: one file per channel per run, sorted by time.
std::string recording_name(const std::string& channel) {
  std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
  return channel + "-" + stamp + mc::replay::kRecordingSuffix;
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
  std::vector<std::shared_ptr<mc::app::Recorder>> recorders;
  std::mutex recorders_mutex;  // an edge starts its recorders from its own thread
  auto record = [&](const std::shared_ptr<mc::relay::Channel>& channel) {
    const auto path = (std::filesystem::path(options->record_dir) / recording_name(channel->name())).string();
    // A recording that cannot start is logged; the broadcast goes on.
    std::string why;
    auto rec = mc::app::Recorder::start(channel, path, why);
    std::lock_guard lock(recorders_mutex);
    if (rec) {
      replays.set_live_recording(channel->name(), std::filesystem::path(path).filename().string());
      recorders.push_back(std::move(rec));
    } else {
      mc::relay::log_event("recording_failed", why);
    }
  };
  if (!options->record_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(options->record_dir, ec);
  }
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

  int sig = 0;
  sigwait(&stop_signals, &sig);
  mc::relay::log_event("stopping", sig == SIGTERM ? "SIGTERM" : "SIGINT");
  feeds.stop_all();
  nats.stop();
  server.stop();
  std::lock_guard lock(recorders_mutex);
  for (auto& rec : recorders) rec->stop();
  mc::relay::log_event("stopped");
  return 0;
}
