#include "server/relay/metrics.hpp"

#include <nlohmann/json.hpp>
#include <sstream>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace mc::relay {
namespace {

void counter(std::ostringstream& o, const char* name, const char* help, std::uint64_t v,
             const char* type = "counter") {
  o << "# HELP " << name << ' ' << help << "\n# TYPE " << name << ' ' << type << '\n'
    << name << ' ' << v << '\n';
}

// Prometheus label values escape backslash, quote and newline.
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

}  // namespace

std::string render_metrics(const RelayStats& s, const ChannelRegistry& channels) {
  std::ostringstream o;
  counter(o, "matchcast_clients", "Spectators connected now", static_cast<std::uint64_t>(std::max<std::int64_t>(0, s.clients.load())), "gauge");
  counter(o, "matchcast_connections_total", "WebSocket connections accepted", s.connections_total.load());
  counter(o, "matchcast_messages_sent_total", "WebSocket messages written", s.messages_sent.load());
  counter(o, "matchcast_writes_total", "Gathered socket writes (one per batch of messages)", s.writes.load());
  counter(o, "matchcast_partial_writes_total", "Batches the kernel took only part of at once", s.partial_writes.load());
  counter(o, "matchcast_bytes_sent_total", "WebSocket bytes written (frames with their headers)", s.bytes_sent.load());
  counter(o, "matchcast_frames_dropped_total", "Frames skipped for slow spectators", s.frames_dropped.load());
  counter(o, "matchcast_closed_slow_total", "Spectators closed for stalling", s.closed_slow.load());
  counter(o, "matchcast_refused_full_total", "Connections refused at max-clients", s.refused_full.load());
  counter(o, "matchcast_refused_per_ip_total", "Connections refused at max-connections-per-ip", s.refused_per_ip.load());
  counter(o, "matchcast_refused_origin_total", "Upgrades refused by the origin allow-list", s.refused_origin.load());
  counter(o, "matchcast_inbound_rejected_total", "Spectator messages over the size or rate limit", s.inbound_rejected.load());
  counter(o, "matchcast_http_requests_total", "HTTP requests", s.http_requests.load());
  counter(o, "matchcast_queue_bytes", "Bytes waiting in all spectators' send queues", static_cast<std::uint64_t>(std::max<std::int64_t>(0, s.queued_bytes.load())), "gauge");
  counter(o, "matchcast_heap_trims_total", "Free heap pages given back to the system (malloc_trim)", s.heap_trims.load());
  o << "# HELP matchcast_heap_trim_seconds_total Time the heap trims took\n# TYPE matchcast_heap_trim_seconds_total counter\n"
    << "matchcast_heap_trim_seconds_total " << static_cast<double>(s.heap_trim_us.load()) / 1e6 << '\n';
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
  // What the heap holds for the program and what it keeps free: a leak
  // grows the first, fragmentation the second.
  const struct mallinfo2 mi = ::mallinfo2();
  counter(o, "matchcast_heap_in_use_bytes", "Heap bytes allocated by the program (mallinfo2)", mi.uordblks + mi.hblkhd, "gauge");
  counter(o, "matchcast_heap_free_bytes", "Heap bytes free inside the heap's arenas (mallinfo2)", mi.fordblks, "gauge");
#endif

  o << "# HELP matchcast_frame_delay_ms Publish to end of write, per spectator frame\n"
       "# TYPE matchcast_frame_delay_ms histogram\n";
  std::uint64_t cumulative = 0;
  for (std::size_t i = 0; i < RelayStats::kDelayBucketsMs.size(); ++i) {
    cumulative += s.delay_buckets[i].load();
    o << "matchcast_frame_delay_ms_bucket{le=\"" << RelayStats::kDelayBucketsMs[i] << "\"} " << cumulative << '\n';
  }
  cumulative += s.delay_buckets.back().load();
  o << "matchcast_frame_delay_ms_bucket{le=\"+Inf\"} " << cumulative << '\n'
    << "matchcast_frame_delay_ms_sum " << static_cast<double>(s.delay_sum_us.load()) / 1000.0 << '\n'
    << "matchcast_frame_delay_ms_count " << s.delay_count.load() << '\n';

  o << "# HELP matchcast_channel_spectators Spectators per channel\n# TYPE matchcast_channel_spectators gauge\n";
  for (const auto& ch : channels.all())
    o << "matchcast_channel_spectators{channel=\"" << label(ch->name()) << "\"} " << ch->subscribers() << '\n';
  o << "# HELP matchcast_channel_frames_total Frames published per channel\n# TYPE matchcast_channel_frames_total counter\n";
  for (const auto& ch : channels.all())
    o << "matchcast_channel_frames_total{channel=\"" << label(ch->name()) << "\"} " << ch->frames_published() << '\n';
  o << "# HELP matchcast_feed_up Feed state per channel (1 = live)\n# TYPE matchcast_feed_up gauge\n";
  for (const auto& ch : channels.all())
    o << "matchcast_feed_up{channel=\"" << label(ch->name()) << "\",state=\"" << feed_state_name(ch->feed_state())
      << "\"} " << (ch->feed_state() == FeedState::Live ? 1 : 0) << '\n';
  o << channels.provider_metrics();  // a NATS edge's own counters
  return o.str();
}

std::string render_channels(const ChannelRegistry& channels) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& ch : channels.all())
    list.push_back({{"name", ch->name()},
                    {"spectators", ch->subscribers()},
                    {"frames", ch->frames_published()},
                    {"feed", feed_state_name(ch->feed_state())}});
  return nlohmann::json{{"channels", list}}.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace mc::relay
