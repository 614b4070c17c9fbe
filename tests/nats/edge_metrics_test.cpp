// The edge's /metrics text from a report, without NATS: every series the
// issue asks for, the lag histogram's cumulative buckets, per-game counters.
#include "server/nats/edge_metrics.hpp"

#include <gtest/gtest.h>

#include <string>

namespace mc::nats {
namespace {

bool has_line(const std::string& text, const std::string& line) {
  return text.find("\n" + line + "\n") != std::string::npos || text.rfind(line + "\n", 0) == 0;
}

TEST(NatsEdgeMetrics, LagHistogramCountsEachFrameInItsBucket) {
  LagHistogram h;
  h.record(0);
  h.record(3);     // (2, 5]
  h.record(5);     // (2, 5]
  h.record(7000);  // past 5000
  EXPECT_EQ(h.count, 4u);
  EXPECT_EQ(h.counts[0], 1u);
  EXPECT_EQ(h.counts[2], 2u);
  EXPECT_EQ(h.counts.back(), 1u);
  EXPECT_EQ(h.sum_ms, 7008u);
  EXPECT_EQ(h.last_ms, 7000u);
  LagHistogram other;
  other.record(4);
  h.add(other);
  EXPECT_EQ(h.count, 5u);
  EXPECT_EQ(h.counts[2], 3u);
  EXPECT_EQ(h.last_ms, 7000u);  // the worst latest of the games added
}

TEST(NatsEdgeMetrics, RendersTheEdgesCountersAsPrometheusText) {
  EdgeReport r;
  r.connected = true;
  r.messages_in = 1200;
  r.bytes_in = 340000;
  r.reconnects = 2;
  r.fetches_found = 3;
  r.fetches_not_found = 1;
  r.on_demand_requested = 2;
  r.on_demand_found = 1;
  r.on_demand_unknown = 1;
  EdgeReport::Game g;
  g.name = "final";
  g.ready = true;
  g.stats.applied = 1100;
  g.stats.gaps = 1;
  g.stats.lag.record(4);
  g.stats.lag.record(30);
  EdgeReport::Game waiting;
  waiting.name = "semi-1";
  waiting.stats.lag.record(700);
  r.games = {g, waiting};
  const std::string m = render_edge_metrics(r);
  for (const char* line : {
           "matchcast_edge_nats_connected 1",
           "matchcast_edge_nats_messages_in_total 1200",
           "matchcast_edge_nats_bytes_in_total 340000",
           "matchcast_edge_nats_reconnects_total 2",
           "matchcast_edge_snapshot_fetches_total{result=\"found\"} 3",
           "matchcast_edge_snapshot_fetches_total{result=\"not_found\"} 1",
           "matchcast_edge_snapshot_fetches_total{result=\"failed\"} 0",
           "matchcast_edge_games{state=\"ready\"} 1",
           "matchcast_edge_games{state=\"waiting\"} 1",
           "matchcast_edge_on_demand_total{result=\"requested\"} 2",
           "matchcast_edge_on_demand_total{result=\"unknown\"} 1",
           "matchcast_edge_origin_lag_ms_bucket{le=\"2\"} 0",
           "matchcast_edge_origin_lag_ms_bucket{le=\"5\"} 1",
           "matchcast_edge_origin_lag_ms_bucket{le=\"50\"} 2",
           "matchcast_edge_origin_lag_ms_bucket{le=\"1000\"} 3",
           "matchcast_edge_origin_lag_ms_bucket{le=\"+Inf\"} 3",
           "matchcast_edge_origin_lag_ms_sum 734",
           "matchcast_edge_origin_lag_ms_count 3",
           "matchcast_edge_origin_lag_last_ms{channel=\"final\"} 30",
           "matchcast_edge_origin_lag_last_ms{channel=\"semi-1\"} 700",
           "matchcast_edge_applied_total{channel=\"final\"} 1100",
           "matchcast_edge_gaps_total{channel=\"final\"} 1",
           "# TYPE matchcast_edge_origin_lag_ms histogram",
           "# TYPE matchcast_edge_games gauge",
       })
    EXPECT_TRUE(has_line(m, line)) << line << "\nin:\n" << m;
}

}  // namespace
}  // namespace mc::nats
