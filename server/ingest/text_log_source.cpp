#include "server/ingest/text_log_source.hpp"

#include "server/ingest/event_queue.hpp"
#include "server/ingest/line_reader.hpp"
#include "server/ingest/show_sequencer.hpp"
#include "server/ingest/state_copy.hpp"
#include "server/ingest/text_show.hpp"

namespace mc::ingest {

namespace {

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

class TextLogSource final : public StateSource {
 public:
  explicit TextLogSource(std::unique_ptr<ByteSource> src) : src_(std::move(src)), lines_(*src_) {}

  bool next(WorldState& out) override {
    std::string_view line;
    std::uint64_t offset = 0;
    for (;;) {
      const auto r = lines_.next(line, offset);
      stats_.bytes = lines_.bytes_read();
      if (r == LineReader::Result::End) {
        if (!src_->error().empty() && !reported_source_error_) {
          reported_source_error_ = true;
          record_skip(stats_, "input ends badly after decoded offset " +
                                  std::to_string(lines_.bytes_read()) + ": " + src_->error());
        }
        return false;
      }
      if (r == LineReader::Result::TooLong) {
        record_skip(stats_, [&] { return "line at offset " + std::to_string(offset) + ": too long, skipped"; });
        continue;
      }
      if (handle_line(line, offset, out)) return true;
    }
  }
  const GameParams& params() const override { return params_; }
  const IngestStats& stats() const override { return stats_; }
  bool poll_event(SourceEvent& out) override { return events_.pop(out); }

 private:
  // Returns true when `line` was a show now stored in `out`.
  bool handle_line(std::string_view line, std::uint64_t offset, WorldState& out) {
    std::size_t i = 0;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    line.remove_prefix(i);
    if (line.empty()) return false;
    if (!header_seen_) {
      header_seen_ = true;
      if (starts_with(line, "ULG")) return false;
      // No header: try the line as a record anyway (a hand-made fragment).
    }
    std::string err;
    bool ok = true;
    if (starts_with(line, "(show ")) {
      ShowExtras extras;
      // Parsed into a scratch state so that a bad record leaves `out`
      // holding the last good state.
      if (parse_text_show(line, scratch_, extras, err)) {
        if (extras.has_play_mode) play_mode_ = scratch_.play_mode;
        if (extras.has_team) {
          left_ = scratch_.left;
          right_ = scratch_.right;
        }
        scratch_.play_mode = play_mode_;
        scratch_.left = left_;
        scratch_.right = right_;
        seq_.stamp(scratch_);
        copy_state(scratch_, out);
        ++stats_.shows;
        return true;
      }
      ok = false;
    } else if (starts_with(line, "(playmode ")) {
      int t = 0;
      PlayMode pm{};
      ok = parse_playmode_record(line, t, pm, err);
      if (ok) play_mode_ = pm;
    } else if (starts_with(line, "(team ")) {
      int t = 0;
      TeamInfo l, r;
      ok = parse_team_record(line, t, l, r, err);
      if (ok) {
        left_ = std::move(l);
        right_ = std::move(r);
      }
    } else if (starts_with(line, "(msg ")) {
      SourceEvent ev;
      ok = parse_msg_record(line, ev.message, err);
      if (ok) {
        ev.kind = SourceEvent::Kind::Message;
        ev.next_index = seq_.next_index();
        events_.push(std::move(ev), stats_);
      }
    } else if (starts_with(line, "(server_param ")) {
      ok = parse_param_record(line, "server_param", params_.server, err);
    } else if (starts_with(line, "(player_param ")) {
      ok = parse_param_record(line, "player_param", params_.player, err);
    } else if (starts_with(line, "(player_type ")) {
      ok = parse_player_type_record(line, params_, err);
    } else {
      ok = false;
      err = "unknown record";
    }
    if (!ok) record_skip(stats_, [&] { return "line at offset " + std::to_string(offset) + ": " + err; });
    return false;
  }

  std::unique_ptr<ByteSource> src_;
  LineReader lines_;
  GameParams params_;
  IngestStats stats_;
  EventQueue events_;
  ShowSequencer seq_;
  WorldState scratch_;
  PlayMode play_mode_ = PlayMode::Null;
  TeamInfo left_, right_;
  bool header_seen_ = false;
  bool reported_source_error_ = false;
};

}  // namespace

std::unique_ptr<StateSource> make_text_log_source(std::unique_ptr<ByteSource> src) {
  return std::make_unique<TextLogSource>(std::move(src));
}

}  // namespace mc::ingest
