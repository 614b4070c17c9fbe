#include "server/ingest/monitor_stream.hpp"

#include "server/ingest/state_copy.hpp"

namespace mc::ingest {

bool MonitorStream::push(std::string_view datagram, WorldState& out) {
  const std::uint64_t n = datagrams_++;
  stats_.bytes += datagram.size();
  error_.clear();
  // Decoded into a scratch state: a bad show must not clobber `out`.
  switch (decoder_.decode(datagram, scratch_, msg_, error_)) {
    case MonitorDecoder::Kind::Show:
      seq_.stamp(scratch_);
      copy_state(scratch_, out);
      ++stats_.shows;
      return true;
    case MonitorDecoder::Kind::Message:
      queue_message(SourceEvent::Kind::Message);
      return false;
    case MonitorDecoder::Kind::Reply:
      queue_message(SourceEvent::Kind::ServerReply);
      return false;
    case MonitorDecoder::Kind::Params:
    case MonitorDecoder::Kind::Ignored:
      return false;
    case MonitorDecoder::Kind::Error:
      break;
  }
  // The text only where it is kept: a flood of garbage datagrams costs a
  // count, not a string each.
  record_skip(stats_, [&] { return "datagram " + std::to_string(n) + ": " + error_; });
  return false;
}

void MonitorStream::queue_message(SourceEvent::Kind kind) {
  SourceEvent ev;
  ev.kind = kind;
  ev.next_index = seq_.next_index();
  ev.message = std::move(msg_);
  msg_ = MessageRecord{};
  events_.push(std::move(ev), stats_);
}

void MonitorStream::refuse_oversized(std::size_t size) {
  const std::uint64_t n = datagrams_++;
  record_skip(stats_, "datagram " + std::to_string(n) + ": oversized datagram (" + std::to_string(size) + " bytes)");
}

void MonitorStream::push_event(SourceEvent::Kind kind, std::string detail) {
  SourceEvent ev;
  ev.kind = kind;
  ev.next_index = seq_.next_index();
  ev.detail = std::move(detail);
  events_.push(std::move(ev), stats_);
}

}  // namespace mc::ingest
