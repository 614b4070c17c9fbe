#include "server/tools/loadgen/soak.hpp"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <array>
#include <atomic>
#include <cstdio>
#include <deque>
#include <future>
#include <memory>
#include <thread>
#include <vector>

#include "server/tools/loadgen/load_client.hpp"

namespace net = boost::asio;

namespace mc::loadgen {
namespace {

using Clock = std::chrono::steady_clock;

// One client thread: its io_context, its clients and their counters. Only
// that thread touches `clients` and `stats` (the main loop posts to it).
struct Worker {
  struct Entry {
    std::shared_ptr<LoadClient> client;
    Behaviour behaviour;
    bool burst = false;
    Clock::time_point leave_at = Clock::time_point::max();  // bursts leave on their own
  };
  net::io_context ioc{1};
  std::deque<Entry> clients;  // oldest first
  std::array<ClientStats, 3> stats;
  std::uint64_t joins = 0, leaves = 0;
  // Set by Population::stop_all(): the clients open just before (the final
  // report's "open").
  bool stopped = false;
  unsigned open_at_stop[3] = {0, 0, 0};
  unsigned burst_open_at_stop = 0;
  std::thread thread;
};

class Population {
 public:
  Population(const SoakOptions& o, const proto::Hello& hello) : o_(o), hello_(hello) {
    for (unsigned t = 0; t < std::max(1u, o.threads); ++t) workers_.push_back(std::make_unique<Worker>());
    for (auto& w : workers_) {
      guards_.push_back(net::make_work_guard(w->ioc));
      w->thread = std::thread([&ioc = w->ioc] { ioc.run(); });
    }
  }
  ~Population() {
    for (auto& w : workers_)
      net::post(w->ioc, [w = w.get()] {
        for (auto& e : w->clients) e.client->stop();
        w->clients.clear();
      });
    guards_.clear();
    for (auto& w : workers_) w->thread.join();
  }

  // On worker `w`'s thread: one more client.
  void join(Worker& w, Behaviour b, bool burst = false) {
    ClientOptions co;
    co.server = net::ip::tcp::endpoint(net::ip::make_address(o_.host), o_.port);
    // Spread the sources over 127.0.0.1-8: churn leaves many ports in TIME_WAIT.
    co.source = net::ip::make_address_v4(0x7F000001u + static_cast<unsigned>(next_source_++ % 8));
    co.host = o_.host;
    co.target = o_.target;
    co.behaviour = b;
    co.decode = !o_.header_only;
    co.skeleton = &hello_.skeleton;
    if (b == Behaviour::Stalled) co.stall_for = o_.stall_for;
    Worker::Entry e{std::make_shared<LoadClient>(w.ioc, co, w.stats[static_cast<int>(b)]), b, burst};
    if (burst) e.leave_at = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o_.burst_stay_s));
    e.client->start();
    w.clients.push_back(std::move(e));
    ++w.joins;
  }

  // Posts `f(worker)` to every worker.
  template <class F>
  void each(F f) {
    for (auto& w : workers_) net::post(w->ioc, [w = w.get(), f] { f(*w); });
  }

  // The first clients, `per_tick` at a time.
  void ramp(unsigned healthy, unsigned stalled) {
    const auto start = Clock::now();
    for (unsigned i = 0; i < healthy + stalled; ++i) {
      const Behaviour b = i % 100 == 99 && i / 100 < stalled ? Behaviour::Stalled : Behaviour::Healthy;
      auto& w = *workers_[i % workers_.size()];
      net::post(w.ioc, [this, &w, b] { join(w, b); });
      std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(
                                                std::chrono::duration<double>((i + 1) / o_.ramp_per_s)));
    }
  }

  // Once a second: churn, stalled clients that have settled, clients the
  // relay closed, bursts that are over.
  void tick(bool burst_now) {
    const unsigned n = static_cast<unsigned>(workers_.size());
    for (unsigned t = 0; t < n; ++t) {
      const unsigned churn = o_.churn / n + (t < o_.churn % n ? 1 : 0);
      const unsigned burst = burst_now ? o_.burst / n + (t < o_.burst % n ? 1 : 0) : 0;
      net::post(workers_[t]->ioc, [this, w = workers_[t].get(), churn, burst] {
        const auto now = Clock::now();
        unsigned to_leave = churn;
        std::deque<Worker::Entry> kept;
        unsigned rejoin_healthy = 0, rejoin_stalled = 0;
        for (auto& e : w->clients) {
          bool leave = false;
          if (e.burst) {
            leave = now >= e.leave_at || e.client->ended();
          } else if (e.behaviour == Behaviour::Stalled) {
            // Found out whether it was cut: a new stalled one takes its place.
            if (e.client->stall_settled() || e.client->ended()) {
              leave = true;
              ++rejoin_stalled;
            }
          } else if (e.client->ended()) {
            leave = true;  // closed by the relay (or could not connect): replaced
            ++rejoin_healthy;
          } else if (to_leave > 0 && e.client->open()) {
            --to_leave;
            leave = true;
            ++rejoin_healthy;
          }
          if (leave) {
            e.client->stop();
            ++w->leaves;
          } else {
            kept.push_back(std::move(e));
          }
        }
        w->clients.swap(kept);
        for (unsigned i = 0; i < rejoin_healthy; ++i) join(*w, Behaviour::Healthy);
        for (unsigned i = 0; i < rejoin_stalled; ++i) join(*w, Behaviour::Stalled);
        for (unsigned i = 0; i < burst; ++i) join(*w, Behaviour::Healthy, true);
      });
    }
  }

  // Ends every client, on its worker, and waits: one still upgrading at the
  // end counts as abandoned before the final report, not after it (the
  // relay may finish its upgrade and count it; /metrics is compared with
  // this report).
  void stop_all() {
    std::vector<std::future<void>> done;
    for (auto& w : workers_) {
      auto p = std::make_shared<std::promise<void>>();
      done.push_back(p->get_future());
      net::post(w->ioc, [w = w.get(), p] {
        for (auto& e : w->clients) {
          if (e.client->open()) {
            if (e.burst) ++w->burst_open_at_stop;
            else ++w->open_at_stop[static_cast<int>(e.behaviour)];
          }
          e.client->stop();
        }
        w->stopped = true;
        p->set_value();
      });
    }
    for (auto& f : done) f.get();
  }

  // Counters of every worker, merged, and how many clients are open.
  void report(double t, bool final) {
    struct Snapshot {
      std::array<ClientStats, 3> stats;
      unsigned open[3] = {0, 0, 0};
      unsigned burst_open = 0;
      std::uint64_t joins = 0, leaves = 0;
    };
    std::vector<std::future<Snapshot>> futures;
    for (auto& w : workers_) {
      auto p = std::make_shared<std::promise<Snapshot>>();
      futures.push_back(p->get_future());
      net::post(w->ioc, [w = w.get(), p] {
        Snapshot s;
        s.stats = w->stats;
        if (w->stopped) {
          for (int b = 0; b < 3; ++b) s.open[b] = w->open_at_stop[b];
          s.burst_open = w->burst_open_at_stop;
        }
        for (const auto& e : w->clients) {
          if (!e.client->open()) continue;
          if (e.burst) ++s.burst_open;
          else ++s.open[static_cast<int>(e.behaviour)];
        }
        s.joins = w->joins;
        s.leaves = w->leaves;
        p->set_value(std::move(s));
      });
    }
    Snapshot all;
    for (auto& f : futures) {
      Snapshot s = f.get();
      for (int b = 0; b < 3; ++b) {
        all.stats[b].merge(s.stats[b]);
        all.open[b] += s.open[b];
      }
      all.burst_open += s.burst_open;
      all.joins += s.joins;
      all.leaves += s.leaves;
    }
    const ClientStats& h = all.stats[0];
    const ClientStats& st = all.stats[2];
    auto u = [](std::uint64_t v) { return static_cast<unsigned long long>(v); };
    std::printf(
        "{\"t\":%.1f,\"final\":%s,\"open\":{\"healthy\":%u,\"stalled\":%u,\"burst\":%u},\"joins\":%llu,\"leaves\":%llu,"
        "\"healthy\":{\"connected\":%llu,\"failed\":%llu,\"abandoned\":%llu,\"closed_by_server\":%llu,\"messages\":%llu,\"frames\":%llu,"
        "\"gaps\":%llu,\"resync_gaps\":%llu,\"frames_skipped\":%llu,\"out_of_order\":%llu,\"decode_errors\":%llu,"
        "\"delay_p50_ms\":%.1f,\"delay_p99_ms\":%.1f,\"delay_max_ms\":%.1f,\"first_error\":\"%s\"},"
        "\"stalled\":{\"connected\":%llu,\"failed\":%llu,\"abandoned\":%llu,\"cut\":%llu,\"not_cut\":%llu,\"messages\":%llu}}\n",
        t, final ? "true" : "false", all.open[0], all.open[2], all.burst_open, u(all.joins), u(all.leaves),
        u(h.connected), u(h.failed), u(h.abandoned), u(h.closed_by_server), u(h.messages), u(h.frames), u(h.gaps), u(h.resync_gaps),
        u(h.frames_skipped), u(h.out_of_order), u(h.decode_errors), h.delay.quantile(0.5), h.delay.quantile(0.99),
        h.delay.max(), h.first_error.substr(0, 80).c_str(), u(st.connected), u(st.failed), u(st.abandoned), u(st.stalled_cut),
        u(st.stalled_not_cut), u(st.messages));
    std::fflush(stdout);
  }

 private:
  const SoakOptions& o_;
  const proto::Hello& hello_;
  std::vector<std::unique_ptr<Worker>> workers_;
  std::vector<net::executor_work_guard<net::io_context::executor_type>> guards_;
  std::atomic<std::uint64_t> next_source_{0};  // joins run on every worker
};

}  // namespace

int run_soak(const SoakOptions& o, const proto::Hello& hello) {
  Population population(o, hello);
  const unsigned stalled = static_cast<unsigned>(o.clients * o.stalled_share);
  const auto start = Clock::now();
  population.ramp(o.clients - stalled, stalled);
  auto next_tick = Clock::now() + std::chrono::seconds(1);
  auto next_report = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.report_every_s));
  auto next_burst = o.burst_every_s > 0 && o.burst > 0
                        ? start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.burst_every_s))
                        : Clock::time_point::max();
  const auto end = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.duration_s));
  while (Clock::now() < end) {
    std::this_thread::sleep_until(std::min({next_tick, next_report, end}));
    const auto now = Clock::now();
    if (now >= next_tick) {
      // A burst whose stay would outlast the run is not started: it would
      // only be stopped mid-upgrade by the end (hundreds of clients counted
      // as abandoned, which blurs the /metrics check).
      const auto stay = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.burst_stay_s));
      const bool due = now >= next_burst;
      const bool burst = due && end - now > stay;
      if (due)
        next_burst += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.burst_every_s));
      population.tick(burst);
      next_tick += std::chrono::seconds(1);
    }
    if (now >= next_report) {
      population.report(std::chrono::duration<double>(now - start).count(), false);
      next_report += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.report_every_s));
    }
  }
  population.stop_all();
  population.report(std::chrono::duration<double>(Clock::now() - start).count(), true);
  return 0;
}

}  // namespace mc::loadgen
