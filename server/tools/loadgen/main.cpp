// matchcast-loadgen: N WebSocket spectators against a relay on loopback.
// Prints delivered messages/s and bytes/s, the frame delay (server stamp to
// receipt) p50/p99/max per behaviour, sequence continuity, decode errors,
// and the server's CPU and memory when given its pid.
#include <sys/resource.h>
#include <unistd.h>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <boost/program_options.hpp>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <thread>

#include "proto/hello.hpp"
#include "server/tools/loadgen/load_client.hpp"
#include "server/tools/loadgen/proc_stats.hpp"
#include "server/tools/loadgen/soak.hpp"

namespace po = boost::program_options;
namespace net = boost::asio;
namespace beast = boost::beast;
using namespace mc::loadgen;

namespace {

struct Options {
  std::string host = "127.0.0.1";
  unsigned short port = 8080;
  std::string target = "/ws";
  unsigned clients = 100;
  double duration_s = 10;
  double ramp_per_s = 2000;
  double slow_share = 0, stalled_share = 0;
  unsigned slow_pause_ms = 200;
  unsigned threads = 1;
  int server_pid = 0;
  bool header_only = false;
  int nice = 10;
  // --soak (soak.hpp): a changing population and a JSON line every few seconds.
  bool soak = false;
  unsigned churn = 20, burst = 500;
  double burst_every_s = 300, burst_stay_s = 60, report_every_s = 10;
  unsigned stall_for_ms = 30000;
};

// One synchronous connection to read the hello: the skeleton every client decodes with.
bool fetch_hello(const Options& o, mc::proto::Hello& hello, std::string& error) {
  try {
    net::io_context ioc;
    beast::websocket::stream<net::ip::tcp::socket> ws(ioc);
    ws.next_layer().connect({net::ip::make_address(o.host), o.port});
    ws.handshake(o.host, o.target);
    beast::flat_buffer buf;
    ws.read(buf);
    if (ws.got_binary()) {
      error = "first message was not the hello";
      return false;
    }
    const std::string text = beast::buffers_to_string(buf.data());
    ws.close(beast::websocket::close_code::normal);
    return mc::proto::hello_from_json(text, hello, error);
  } catch (const std::exception& e) {
    error = e.what();
    return false;
  }
}

// The first three fields of /proc/loadavg: other work on the machine
// shows in every figure above, so it is printed with them.
std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

void raise_fd_limit() {
  rlimit r{};
  if (getrlimit(RLIMIT_NOFILE, &r) == 0 && r.rlim_cur < r.rlim_max) {
    r.rlim_cur = r.rlim_max;
    setrlimit(RLIMIT_NOFILE, &r);
  }
}

void print_group(const char* name, unsigned count, const ClientStats& s, double seconds) {
  if (count == 0) return;
  std::printf("%-8s clients %6u: connected %llu, failed %llu, closed by server %llu\n", name, count,
              static_cast<unsigned long long>(s.connected), static_cast<unsigned long long>(s.failed),
              static_cast<unsigned long long>(s.closed_by_server));
  std::printf("         delivered %.0f msg/s, %.2f MB/s, %llu frames\n", s.messages / seconds,
              s.bytes / seconds / 1e6, static_cast<unsigned long long>(s.frames));
  std::printf("         frame delay p50 %.1f ms, p99 %.1f ms, max %.1f ms (%llu samples)\n",
              s.delay.quantile(0.5), s.delay.quantile(0.99), s.delay.max(),
              static_cast<unsigned long long>(s.delay.count()));
  std::printf("         sequence: %llu gaps (%llu frames skipped by the relay), %llu out of order, "
              "%llu decode errors\n",
              static_cast<unsigned long long>(s.gaps), static_cast<unsigned long long>(s.frames_skipped),
              static_cast<unsigned long long>(s.out_of_order),
              static_cast<unsigned long long>(s.decode_errors));
  if (!s.first_error.empty()) std::printf("         first error: %s\n", s.first_error.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  po::options_description desc("matchcast-loadgen: simulated spectators for a Matchcast relay\n\nOptions");
  // clang-format off
  desc.add_options()
    ("help,h", "print this help")
    ("host", po::value(&o.host)->default_value(o.host), "relay address (loopback only)")
    ("port", po::value(&o.port)->default_value(o.port), "relay port")
    ("target", po::value(&o.target)->default_value(o.target), "WebSocket path")
    ("clients,n", po::value(&o.clients)->default_value(o.clients), "spectators")
    ("duration", po::value(&o.duration_s)->default_value(o.duration_s), "seconds to measure after the ramp")
    ("ramp", po::value(&o.ramp_per_s)->default_value(o.ramp_per_s), "new connections per second")
    ("slow", po::value(&o.slow_share)->default_value(0), "share of clients that read slowly (0..1)")
    ("slow-pause-ms", po::value(&o.slow_pause_ms)->default_value(o.slow_pause_ms), "pause between a slow client's reads")
    ("stalled", po::value(&o.stalled_share)->default_value(0), "share of clients that never read (0..1)")
    ("threads", po::value(&o.threads)->default_value(o.threads), "client threads")
    ("server-pid", po::value(&o.server_pid)->default_value(0), "relay's pid, for its CPU and memory")
    ("header-only", po::bool_switch(&o.header_only), "check headers only, skip the full decode")
    ("nice", po::value(&o.nice)->default_value(o.nice),
     "scheduling niceness of the client threads (0: compete with the relay as equals)")
    ("soak", po::bool_switch(&o.soak),
     "long run (scripts/soak.sh): churn, bursts, stalled clients that come back to see if they were cut off; "
     "a JSON line of counters every --report-every seconds")
    ("churn", po::value(&o.churn)->default_value(o.churn), "--soak: healthy clients leaving and joining each second")
    ("burst", po::value(&o.burst)->default_value(o.burst), "--soak: clients joining at once every --burst-every s")
    ("burst-every", po::value(&o.burst_every_s)->default_value(o.burst_every_s), "--soak: seconds between bursts (0: none)")
    ("burst-stay", po::value(&o.burst_stay_s)->default_value(o.burst_stay_s), "--soak: seconds a burst's clients stay")
    ("stall-for-ms", po::value(&o.stall_for_ms)->default_value(o.stall_for_ms),
     "--soak: a stalled client reads again after this long, to see whether the relay cut it off")
    ("report-every", po::value(&o.report_every_s)->default_value(o.report_every_s), "--soak: seconds between reports");
  // clang-format on
  try {
    po::variables_map vm;
    po::store(po::parse_command_line(argc, argv, desc), vm);
    if (vm.count("help")) {
      std::cout << desc << "\n";
      return 0;
    }
    po::notify(vm);
  } catch (const po::error& e) {
    std::fprintf(stderr, "matchcast-loadgen: %s\n", e.what());
    return 2;
  }
  raise_fd_limit();
  if (o.threads == 0) o.threads = 1;
  // The clients stand in for spectators on other machines. On the relay's
  // own machine they share its cores; at equal priority the scheduler hands
  // a core to a client thread on every message it is woken for, and the
  // relay's fan-out stretches. Lower priority lets the relay send a frame
  // through; the delay measured still includes the clients' own time.
  // Set before any thread starts: threads inherit it.
  if (o.nice != 0 && ::setpriority(PRIO_PROCESS, 0, o.nice) != 0)
    std::fprintf(stderr, "matchcast-loadgen: cannot set niceness %d; going on at the current one\n", o.nice);

  // Headers alone need no skeleton, and so no hello: then any server that
  // sends Matchcast frame headers can be measured (bench-fanout's anchor).
  mc::proto::Hello hello;
  std::string error;
  if (!o.header_only && !fetch_hello(o, hello, error)) {
    std::fprintf(stderr, "matchcast-loadgen: cannot read the hello from %s:%u%s: %s\n", o.host.c_str(),
                 o.port, o.target.c_str(), error.c_str());
    return 1;
  }

  if (o.soak) {
    mc::loadgen::SoakOptions so;
    so.host = o.host;
    so.port = o.port;
    so.target = o.target;
    so.clients = o.clients;
    so.stalled_share = o.stalled_share;
    so.stall_for = std::chrono::milliseconds(o.stall_for_ms);
    so.churn = o.churn;
    so.burst = o.burst;
    so.burst_every_s = o.burst_every_s;
    so.burst_stay_s = o.burst_stay_s;
    so.ramp_per_s = o.ramp_per_s;
    so.duration_s = o.duration_s;
    so.report_every_s = o.report_every_s;
    so.threads = o.threads;
    so.header_only = o.header_only;
    return mc::loadgen::run_soak(so, hello);
  }
  const unsigned n_stalled = static_cast<unsigned>(o.clients * o.stalled_share);
  const unsigned n_slow = static_cast<unsigned>(o.clients * o.slow_share);
  std::vector<std::unique_ptr<net::io_context>> contexts;
  std::vector<std::array<ClientStats, 3>> stats(o.threads);
  for (unsigned t = 0; t < o.threads; ++t) contexts.push_back(std::make_unique<net::io_context>(1));
  std::vector<std::shared_ptr<LoadClient>> clients;
  clients.reserve(o.clients);

  auto server_ep = net::ip::tcp::endpoint(net::ip::make_address(o.host), o.port);
  ProcSample before, cpu_start, cpu_end;
  const bool measure = o.server_pid && sample_process(o.server_pid, before);

  std::vector<std::thread> threads;
  std::vector<net::executor_work_guard<net::io_context::executor_type>> guards;
  for (auto& c : contexts) guards.push_back(net::make_work_guard(*c));
  for (auto& c : contexts) threads.emplace_back([&c] { c->run(); });

  // Ramp: spread connections so the relay sees a realistic arrival.
  const auto ramp_start = std::chrono::steady_clock::now();
  for (unsigned i = 0; i < o.clients; ++i) {
    Behaviour b = i < n_stalled ? Behaviour::Stalled
                  : i < n_stalled + n_slow ? Behaviour::Slow : Behaviour::Healthy;
    ClientOptions co;
    co.server = server_ep;
    // 127.0.0.1 has ~28k ephemeral ports: spread sources over 127.0.0.x.
    co.source = net::ip::make_address_v4(0x7F000001u + (i / 20000));
    co.host = o.host;
    co.target = o.target;
    co.behaviour = b;
    co.slow_read_pause = std::chrono::milliseconds(o.slow_pause_ms);
    co.decode = !o.header_only;
    co.skeleton = &hello.skeleton;
    const unsigned t = i % o.threads;
    auto client = std::make_shared<LoadClient>(*contexts[t], co, stats[t][static_cast<int>(b)]);
    net::post(*contexts[t], [client] { client->start(); });
    clients.push_back(client);
    std::this_thread::sleep_until(ramp_start + std::chrono::duration<double>((i + 1) / o.ramp_per_s));
  }
  // Let the last handshakes finish, then measure from a clean start.
  std::this_thread::sleep_for(std::chrono::seconds(1));
  for (unsigned t = 0; t < o.threads; ++t)
    net::post(*contexts[t], [&s = stats[t]] {
      for (auto& g : s) {
        const auto connected = g.connected, failed = g.failed;
        g = ClientStats{};
        g.connected = connected;
        g.failed = failed;
      }
    });
  if (measure) sample_process(o.server_pid, cpu_start);
  ProcSample self_start, self_end;
  sample_process(::getpid(), self_start);
  const auto t0 = std::chrono::steady_clock::now();
  std::this_thread::sleep_for(std::chrono::duration<double>(o.duration_s));
  if (measure) sample_process(o.server_pid, cpu_end);
  sample_process(::getpid(), self_end);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  for (unsigned t = 0; t < o.threads; ++t)
    net::post(*contexts[t], [&clients, t, n = o.threads] {
      for (std::size_t i = t; i < clients.size(); i += n) clients[i]->stop();
    });
  guards.clear();
  for (auto& th : threads) th.join();

  std::array<ClientStats, 3> total;
  for (auto& s : stats)
    for (int b = 0; b < 3; ++b) total[b].merge(s[b]);
  std::printf("matchcast-loadgen: %u clients on %s:%u%s for %.1f s (%u threads at nice %d, %s)\n", o.clients,
              o.host.c_str(), o.port, o.target.c_str(), seconds, o.threads, ::getpriority(PRIO_PROCESS, 0),
              o.header_only ? "headers checked" : "every frame decoded");
  print_group("healthy", o.clients - n_slow - n_stalled, total[0], seconds);
  print_group("slow", n_slow, total[1], seconds);
  print_group("stalled", n_stalled, total[2], seconds);
  ClientStats all;
  for (auto& s : total) all.merge(s);
  std::printf("all      delivered %.0f msg/s, %.2f MB/s\n", all.messages / seconds, all.bytes / seconds / 1e6);
  if (measure) {
    std::printf("server   cpu %.2f cores, rss %.1f MB (before clients %.1f MB, %.1f KB per client)\n",
                (cpu_end.cpu_seconds - cpu_start.cpu_seconds) / seconds, cpu_end.rss_kb / 1024.0,
                before.rss_kb / 1024.0,
                o.clients ? static_cast<double>(cpu_end.rss_kb - before.rss_kb) / o.clients : 0.0);
  }
  // On one machine the clients compete with the server for the cores.
  std::printf("loadgen  cpu %.2f cores; load average now %s\n",
              (self_end.cpu_seconds - self_start.cpu_seconds) / seconds, load_average().c_str());
  const bool healthy_ok = total[0].failed == 0 && total[0].gaps == 0 && total[0].out_of_order == 0 &&
                          total[0].decode_errors == 0 && total[0].closed_by_server == 0;
  std::printf("healthy clients: %s\n", healthy_ok ? "no drops, no gaps, no errors" : "PROBLEMS (see above)");
  return healthy_ok ? 0 : 3;
}
