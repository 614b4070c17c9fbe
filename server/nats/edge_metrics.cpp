#include "server/nats/edge_metrics.hpp"

#include <sstream>

namespace mc::nats {
namespace {

void head(std::ostringstream& o, const char* name, const char* help, const char* type) {
  o << "# HELP " << name << ' ' << help << "\n# TYPE " << name << ' ' << type << '\n';
}

void one(std::ostringstream& o, const char* name, const char* help, const char* type, std::uint64_t v) {
  head(o, name, help, type);
  o << name << ' ' << v << '\n';
}

// Game names are subject tokens (no quote or backslash); escaped anyway.
std::string label(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '\\' || c == '"') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out;
}

// One counter per game, labelled by channel.
template <class Get>
void per_game(std::ostringstream& o, const EdgeReport& r, const char* name, const char* help, Get get) {
  head(o, name, help, "counter");
  for (const auto& g : r.games) o << name << "{channel=\"" << label(g.name) << "\"} " << get(g.stats) << '\n';
}

}  // namespace

std::string render_edge_metrics(const EdgeReport& r) {
  std::ostringstream o;
  one(o, "matchcast_edge_nats_connected", "1 while the edge's NATS link is up", "gauge", r.connected ? 1 : 0);
  one(o, "matchcast_edge_nats_messages_in_total", "NATS messages received (live subjects and JetStream replies)",
      "counter", r.messages_in);
  one(o, "matchcast_edge_nats_bytes_in_total", "Payload bytes of those messages", "counter", r.bytes_in);
  one(o, "matchcast_edge_nats_reconnects_total", "Times the NATS link came back after a loss", "counter",
      r.reconnects);

  head(o, "matchcast_edge_snapshot_fetches_total", "Snapshot reads from the keyframe stream, by result", "counter");
  o << "matchcast_edge_snapshot_fetches_total{result=\"found\"} " << r.fetches_found << '\n'
    << "matchcast_edge_snapshot_fetches_total{result=\"not_found\"} " << r.fetches_not_found << '\n'
    << "matchcast_edge_snapshot_fetches_total{result=\"failed\"} " << r.fetches_failed << '\n';

  std::uint64_t ready = 0;
  for (const auto& g : r.games) ready += g.ready;
  head(o, "matchcast_edge_games", "Games the edge carries: with their hello (ready) or not yet (waiting)", "gauge");
  o << "matchcast_edge_games{state=\"ready\"} " << ready << '\n'
    << "matchcast_edge_games{state=\"waiting\"} " << r.games.size() - ready << '\n';

  head(o, "matchcast_edge_on_demand_total", "Games spectators asked for that the edge did not carry, by outcome",
       "counter");
  o << "matchcast_edge_on_demand_total{result=\"requested\"} " << r.on_demand_requested << '\n'
    << "matchcast_edge_on_demand_total{result=\"found\"} " << r.on_demand_found << '\n'
    << "matchcast_edge_on_demand_total{result=\"unknown\"} " << r.on_demand_unknown << '\n'
    << "matchcast_edge_on_demand_total{result=\"refused\"} " << r.on_demand_refused << '\n';
  one(o, "matchcast_edge_rejected_subjects_total", "Messages on the prefix that name no acceptable game", "counter",
      r.rejected_subjects);

  // The lag behind the origin, all games together, then each game's latest.
  LagHistogram all;
  for (const auto& g : r.games) all.add(g.stats.lag);
  head(o, "matchcast_edge_origin_lag_ms",
       "Origin's frame timestamp to the frame's publish at this edge (needs clocks in step)", "histogram");
  std::uint64_t cumulative = 0;
  for (std::size_t i = 0; i < LagHistogram::kBucketsMs.size(); ++i) {
    cumulative += all.counts[i];
    o << "matchcast_edge_origin_lag_ms_bucket{le=\"" << LagHistogram::kBucketsMs[i] << "\"} " << cumulative << '\n';
  }
  o << "matchcast_edge_origin_lag_ms_bucket{le=\"+Inf\"} " << all.count << '\n'
    << "matchcast_edge_origin_lag_ms_sum " << all.sum_ms << '\n'
    << "matchcast_edge_origin_lag_ms_count " << all.count << '\n';
  head(o, "matchcast_edge_origin_lag_last_ms", "The lag of each game's latest frame", "gauge");
  for (const auto& g : r.games)
    o << "matchcast_edge_origin_lag_last_ms{channel=\"" << label(g.name) << "\"} " << g.stats.lag.last_ms << '\n';

  per_game(o, r, "matchcast_edge_applied_total", "Messages from NATS passed on to the channel",
           [](const EdgeSyncStats& s) { return s.applied; });
  per_game(o, r, "matchcast_edge_duplicates_total", "Messages already applied (snapshot and live overlap)",
           [](const EdgeSyncStats& s) { return s.duplicates; });
  per_game(o, r, "matchcast_edge_gaps_total", "Times a message number was skipped (lost messages)",
           [](const EdgeSyncStats& s) { return s.gaps; });
  per_game(o, r, "matchcast_edge_held_back_total", "Deltas held back while waiting for a keyframe",
           [](const EdgeSyncStats& s) { return s.held_back; });
  per_game(o, r, "matchcast_edge_rejected_total", "Malformed envelopes or payloads skipped",
           [](const EdgeSyncStats& s) { return s.rejected; });
  per_game(o, r, "matchcast_edge_resyncs_total", "Snapshots applied (start, reconnect, catching up)",
           [](const EdgeSyncStats& s) { return s.resyncs; });
  return o.str();
}

}  // namespace mc::nats
