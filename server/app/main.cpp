// matchcast-server: reads a game, animates it and serves it to spectators.
#include <csignal>
#include <cstdio>
#include <string>

#include "server/app/log_feed.hpp"
#include "server/app/server_options.hpp"
#include "server/relay/log.hpp"
#include "server/relay/relay_server.hpp"

int main(int argc, char** argv) {
  std::string message;
  int exit_code = 0;
  auto options = mc::app::parse_server_options(argc, argv, message, exit_code);
  if (!options) {
    std::fprintf(exit_code ? stderr : stdout, "%s\n", message.c_str());
    return exit_code;
  }

  // Block the stop signals before any thread starts, so that every thread
  // inherits the mask and only sigwait() below sees them.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  std::signal(SIGPIPE, SIG_IGN);

  auto channel = std::make_shared<mc::relay::Channel>("live");
  mc::app::LogFeed feed(options->feed, channel);
  std::string error;
  if (!feed.start(error)) {
    std::fprintf(stderr, "matchcast-server: %s\n", error.c_str());
    return 1;
  }
  mc::relay::RelayServer server(options->relay, channel);
  if (!server.start(error)) {
    std::fprintf(stderr, "matchcast-server: %s\n", error.c_str());
    if (options->relay.port != 0)
      std::fprintf(stderr, "Is another program using port %u? Try --port 0 or --port N.\n",
                   options->relay.port);
    return 1;
  }
  const std::string host =
      options->relay.address == "0.0.0.0" ? "127.0.0.1" : options->relay.address;
  std::printf("Matchcast: open http://%s:%u/\n", host.c_str(), server.port());
  std::fflush(stdout);
  mc::relay::log_event("listening", host + ":" + std::to_string(server.port()));

  int sig = 0;
  sigwait(&stop_signals, &sig);
  mc::relay::log_event("stopping", sig == SIGTERM ? "SIGTERM" : "SIGINT");
  feed.stop();
  server.stop();
  return 0;
}
