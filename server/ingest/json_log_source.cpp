#include "server/ingest/json_log_source.hpp"

#include "server/ingest/event_queue.hpp"
#include "server/ingest/json_records.hpp"
#include "server/ingest/json_splitter.hpp"
#include "server/ingest/show_sequencer.hpp"
#include "server/ingest/state_copy.hpp"

namespace mc::ingest {
namespace {

class JsonLogSource final : public StateSource {
 public:
  explicit JsonLogSource(std::unique_ptr<ByteSource> src) : src_(std::move(src)), split_(*src_) {}

  bool next(WorldState& out) override {
    std::string_view obj;
    std::uint64_t offset = 0;
    for (;;) {
      const auto r = split_.next(obj, offset);
      stats_.bytes = split_.bytes_read();
      if (r == JsonSplitter::Result::End || r == JsonSplitter::Result::Truncated) {
        if (r == JsonSplitter::Result::Truncated)
          record_skip(stats_, "element at offset " + std::to_string(offset) + ": input ends inside it");
        if (!src_->error().empty() && !reported_) {
          reported_ = true;
          record_skip(stats_, "input ends badly: " + src_->error());
        }
        return false;
      }
      if (r == JsonSplitter::Result::TooLong) {
        record_skip(stats_, [&] { return "element at offset " + std::to_string(offset) + ": too long, skipped"; });
        continue;
      }
      RecordKind kind{};
      std::string err;
      MessageRecord msg;
      // Decoded into a scratch state: a bad show must not clobber `out`.
      if (!decode_json_record(obj, ctx_, scratch_, msg, kind, err)) {
        record_skip(stats_, [&] { return "element at offset " + std::to_string(offset) + ": " + err; });
        continue;
      }
      if (kind == RecordKind::Show) {
        seq_.stamp(scratch_);
        copy_state(scratch_, out);
        ++stats_.shows;
        return true;
      }
      if (kind == RecordKind::Msg) {
        SourceEvent ev;
        ev.kind = SourceEvent::Kind::Message;
        ev.next_index = seq_.next_index();
        ev.message = std::move(msg);
        events_.push(std::move(ev), stats_);
      }
    }
  }
  const GameParams& params() const override { return ctx_.params; }
  const IngestStats& stats() const override { return stats_; }
  bool poll_event(SourceEvent& out) override { return events_.pop(out); }

 private:
  std::unique_ptr<ByteSource> src_;
  JsonSplitter split_;
  GameContext ctx_;
  IngestStats stats_;
  EventQueue events_;
  ShowSequencer seq_;
  WorldState scratch_;
  bool reported_ = false;
};

}  // namespace

std::unique_ptr<StateSource> make_json_log_source(std::unique_ptr<ByteSource> src) {
  return std::make_unique<JsonLogSource>(std::move(src));
}

}  // namespace mc::ingest
