#include "server/ingest/binary_log_source.hpp"

#include <array>

#include "server/ingest/binary_records.hpp"
#include "server/ingest/event_queue.hpp"
#include "server/ingest/show_sequencer.hpp"

namespace mc::ingest {
namespace {

using namespace binary;

class BinaryLogSource final : public StateSource {
 public:
  BinaryLogSource(std::unique_ptr<ByteSource> src, LogFormat format)
      : src_(std::move(src)), format_(format) {}

  bool next(WorldState& out) override {
    if (done_) return false;
    if (format_ != LogFormat::BinaryV1 && offset_ == 0) {
      char magic[4];
      if (!read_exact(magic, 4, "header")) return finish();
    }
    for (;;) {
      const std::uint64_t at = offset_;
      if (format_ == LogFormat::BinaryV1) {
        if (!read_exact(buf_.data(), kDispInfoSize, "record")) return finish();
        const std::int16_t mode = be16(buf_.data());
        const std::string_view body(buf_.data() + 2, kDispInfoSize - 2);
        if (mode == kShow) {
          decode_showinfo_v1(body, out);
          for (int i = 0; i < kMaxPlayers; ++i)
            out.players[static_cast<std::size_t>(i)].type = v1_types_[static_cast<std::size_t>(i)];
          play_mode_ = out.play_mode;
          left_ = out.left;
          right_ = out.right;
          return emit(out);
        }
        if (mode == kMsg) push_msg(body, at);
        else if (mode != kDraw && mode != kBlank && mode != kNoInfo)
          record_skip(stats_, [&] {
            return "record at offset " + std::to_string(at) + ": unknown mode " + std::to_string(mode);
          });
        continue;
      }
      char m[2];
      if (!read_exact(m, 2, "record")) return finish();
      const std::int16_t mode = be16(m);
      switch (mode) {
        case kShow: {
          const std::size_t n = format_ == LogFormat::BinaryV2 ? kShowInfoSize : kShortShowInfo2Size;
          if (!read_exact(buf_.data(), n, "show")) return finish();
          const std::string_view body(buf_.data(), n);
          if (format_ == LogFormat::BinaryV2) {
            decode_showinfo_v1(body, out);
            play_mode_ = out.play_mode;
            left_ = out.left;
            right_ = out.right;
          } else {
            decode_short_showinfo2(body, out);
          }
          return emit(out);
        }
        case kMsg: {
          char hdr[4];
          if (!read_exact(hdr, 4, "msg")) return finish();
          const int board = be16(hdr);
          const int len = be16(hdr + 2);
          if (len < 0 || static_cast<std::size_t>(len) > buf_.size() - 2)
            return fail(at, "bad msg length " + std::to_string(len));
          buf_[0] = hdr[0];
          buf_[1] = hdr[1];
          if (!read_exact(buf_.data() + 2, static_cast<std::size_t>(len), "msg")) return finish();
          (void)board;
          push_msg(std::string_view(buf_.data(), static_cast<std::size_t>(len) + 2), at);
          continue;
        }
        case kPlayMode: {
          char c;
          if (!read_exact(&c, 1, "playmode")) return finish();
          const int pm = static_cast<unsigned char>(c);
          if (pm < kPlayModeCount) play_mode_ = static_cast<PlayMode>(pm);
          else record_skip(stats_, [&] { return "record at offset " + std::to_string(at) + ": bad play mode"; });
          continue;
        }
        case kTeam:
          if (!read_exact(buf_.data(), kTeamPairSize, "team")) return finish();
          decode_teams(std::string_view(buf_.data(), kTeamPairSize), left_, right_);
          continue;
        case kPlayerType: {
          if (!read_exact(buf_.data(), kPlayerTypeSize, "player_type")) return finish();
          PlayerType t;
          decode_player_type(std::string_view(buf_.data(), kPlayerTypeSize), t);
          if (!store_player_type(params_, t))
            record_skip(stats_, [&] { return "record at offset " + std::to_string(at) + ": bad player type id"; });
          continue;
        }
        case kParam:
          if (!read_exact(buf_.data(), kServerParamsSize, "server_param")) return finish();
          decode_server_params(std::string_view(buf_.data(), kServerParamsSize), params_.server);
          continue;
        case kPlayerParam:
          // player_params_t: nothing a viewer needs; skipped whole.
          if (!read_exact(buf_.data(), kPlayerParamsSize, "player_param")) return finish();
          continue;
        default:
          // Record sizes depend on the tag: without it there is no way to resync.
          return fail(at, "unknown record mode " + std::to_string(mode) + ", stopping");
      }
    }
  }
  const GameParams& params() const override { return params_; }
  const IngestStats& stats() const override { return stats_; }
  bool poll_event(SourceEvent& out) override { return events_.pop(out); }

 private:
  bool emit(WorldState& out) {
    out.play_mode = play_mode_;
    out.left = left_;
    out.right = right_;
    seq_.stamp(out);
    last_time_ = out.time;
    ++stats_.shows;
    stats_.bytes = offset_;
    return true;
  }
  void push_msg(std::string_view body, std::uint64_t at) {
    SourceEvent ev;
    if (!decode_msginfo(body, ev.message.board, ev.message.text)) {
      record_skip(stats_, [&] { return "record at offset " + std::to_string(at) + ": bad msg"; });
      return;
    }
    ev.message.time = last_time_;
    if (format_ == LogFormat::BinaryV1) apply_change_player_type(ev.message.text, v1_types_);
    ev.next_index = seq_.next_index();
    events_.push(std::move(ev), stats_);
  }
  // Reads exactly n bytes; on a short read records the cut (a truncated log)
  // unless the input ended cleanly on a record boundary.
  bool read_exact(char* dst, std::size_t n, const char* what) {
    std::size_t got = 0;
    while (got < n) {
      const std::size_t k = src_->read(dst + got, n - got);
      if (k == 0) break;
      got += k;
    }
    const std::uint64_t start = offset_;
    offset_ += got;
    if (got == n) return true;
    if (got != 0 || (what != std::string_view("record") && what != std::string_view("header")))
      record_skip(stats_, std::string("truncated ") + what + " at offset " + std::to_string(start));
    if (!src_->error().empty())
      record_skip(stats_, "input ends badly at offset " + std::to_string(offset_) + ": " + src_->error());
    return false;
  }
  bool fail(std::uint64_t at, const std::string& why) {
    record_skip(stats_, [&] { return "record at offset " + std::to_string(at) + ": " + why; });
    return finish();
  }
  bool finish() {
    done_ = true;
    stats_.bytes = offset_;
    return false;
  }

  std::unique_ptr<ByteSource> src_;
  LogFormat format_;
  std::array<char, 8192> buf_{};
  std::uint64_t offset_ = 0;
  bool done_ = false;
  int last_time_ = 0;
  std::array<std::int16_t, kMaxPlayers> v1_types_{};  // v1 shows carry no type
  GameParams params_;
  IngestStats stats_;
  EventQueue events_;
  ShowSequencer seq_;
  PlayMode play_mode_ = PlayMode::Null;
  TeamInfo left_, right_;
};

}  // namespace

std::unique_ptr<StateSource> make_binary_log_source(std::unique_ptr<ByteSource> src,
                                                    LogFormat format) {
  return std::make_unique<BinaryLogSource>(std::move(src), format);
}

}  // namespace mc::ingest
