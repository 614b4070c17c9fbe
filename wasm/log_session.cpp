#include "wasm/log_session.hpp"

#include <nlohmann/json.hpp>

#include "server/ingest/binary_log_source.hpp"
#include "server/ingest/json_log_source.hpp"
#include "server/ingest/text_log_source.hpp"

namespace mc::wasm {
namespace {

// The reader owns its ByteSource; the session keeps the buffer it fills.
class Forward : public ingest::ByteSource {
 public:
  explicit Forward(PushByteSource& to) : to_(to) {}
  std::size_t read(char* dst, std::size_t n) override { return to_.read(dst, n); }
  const std::string& error() const override { return to_.error(); }
  std::uint64_t raw_offset() const override { return to_.raw_offset(); }

 private:
  PushByteSource& to_;
};

// Enough to see past a "ULG6\n" header to the first record (as open_log).
constexpr std::size_t kSniffBytes = 512;

// Why the first bytes are not a log we read, in a reader's words.
std::string not_a_log(std::string_view head) {
  if (head.size() >= 2 && static_cast<unsigned char>(head[0]) == 0x1f && static_cast<unsigned char>(head[1]) == 0x8b)
    return "the data is still gzip-compressed (it was compressed twice?)";
  if (head.size() >= 4 && head.substr(0, 3) == "ULG") {
    const char v = head[3];
    const std::string version = v >= '0' && v <= '9' ? std::string(1, v) : std::to_string(static_cast<unsigned char>(v));
    return "an RCG log of version " + version +
           ", which Matchcast does not read (it reads versions 1 to 6 and the JSON logs)";
  }
  return "not a game log: an .rcg file starts with \"ULG\", \"JSON\", \"[\" or a version 1 record";
}

}  // namespace

LogSession::LogSession(LogSessionOptions options) : options_(std::move(options)) {}
LogSession::~LogSession() = default;

std::size_t LogSession::wants() const {
  if (done_ || failed_ || in_.ended()) return 0;
  const std::size_t need = source_ ? options_.margin_bytes : kSniffBytes;
  return in_.buffered() >= need ? 0 : need - in_.buffered();
}

void put_record(std::string& out, char kind, std::string_view bytes) {
  const auto n = static_cast<std::uint32_t>(bytes.size());
  const char head[5] = {kind, static_cast<char>(n & 0xff), static_cast<char>((n >> 8) & 0xff),
                        static_cast<char>((n >> 16) & 0xff), static_cast<char>(n >> 24)};
  out.append(head, sizeof head);
  out.append(bytes);
}

void LogSession::put(char kind, std::string_view bytes) { put_record(out_, kind, bytes); }

void LogSession::emit() {
  struct Sink : app::PipelineSink {
    LogSession& s;
    explicit Sink(LogSession& session) : s(session) {}
    void control(std::string json) override { s.put('c', json); }
    void frame(std::string bytes, bool key) override { s.put(key ? 'k' : 'f', bytes); }
  } sink(*this);
  // The made-up clock: 50 ms a frame from the base.
  const std::uint64_t base = options_.server_time_base_ms;
  pipeline_->emit_all([base](std::uint32_t seq) { return base + std::uint64_t{seq} * 50; }, sink);
}

void LogSession::fail(std::string why) {
  failed_ = true;
  error_ = std::move(why);
}

bool LogSession::open_reader() {
  const std::string_view head = in_.peek(kSniffBytes);
  if (head.empty()) {
    fail(in_.error().empty() ? "the file is empty" : "no data could be read: " + in_.error());
    return false;
  }
  format_ = ingest::sniff_log_format(head);
  auto src = std::make_unique<Forward>(in_);
  switch (format_) {
    case ingest::LogFormat::TextV4:
    case ingest::LogFormat::TextV5:
    case ingest::LogFormat::TextV6:
      source_ = ingest::make_text_log_source(std::move(src));
      break;
    case ingest::LogFormat::BinaryV1:
    case ingest::LogFormat::BinaryV2:
    case ingest::LogFormat::BinaryV3:
      source_ = ingest::make_binary_log_source(std::move(src), format_);
      break;
    case ingest::LogFormat::Json17:
    case ingest::LogFormat::Json18:
    case ingest::LogFormat::Json19:
      source_ = ingest::make_json_log_source(std::move(src));
      break;
    case ingest::LogFormat::Unknown:
      break;
  }
  if (!source_) {
    fail(not_a_log(head));
    return false;
  }
  return true;
}

void LogSession::finish() {
  if (pipeline_) {
    pipeline_->finish();
    emit();
  }
  done_ = true;
}

LogSession::Status LogSession::step(int max_states) {
  if (failed_) return Status::Failed;
  if (done_) return Status::Done;
  if (!source_) {
    if (wants() > 0) return Status::NeedInput;
    if (!open_reader()) return Status::Failed;
  }

  for (int n = 0; n < max_states; ++n) {
    if (wants() > 0) return n == 0 ? Status::NeedInput : Status::Progress;
    WorldState state;
    const bool got = source_->next(state);
    if (in_.starved()) {
      // The reader met a false end: it cannot resume. What went out stays.
      finish();
      fail("a stretch of the log between two game states is longer than " +
           std::to_string(options_.margin_bytes >> 20) + " MB; it stops at cycle " + std::to_string(last_time_));
      return Status::Failed;
    }
    if (!got) {
      finish();
      if (states_ == 0) {
        fail("the log holds no game states" +
             (source_->stats().errors.empty() ? std::string() : " (" + source_->stats().errors.front() + ")"));
        return Status::Failed;
      }
      return Status::Done;
    }
    if (!pipeline_) {
      put('h', app::make_hello(state, source_->params(), options_.pipeline.keyframe_interval, options_.match_id));
      pipeline_ = std::make_unique<app::BroadcastPipeline>(source_->params(), options_.pipeline);
    }
    pipeline_->push(state);
    emit();
    ++states_;
    last_time_ = state.time;
    if (states_ >= options_.max_states) {
      capped_ = true;
      finish();
      return Status::Done;
    }
  }
  return Status::Progress;
}

std::string LogSession::status_json() const {
  nlohmann::json j;
  j["states"] = states_;
  j["frames"] = pipeline_ ? pipeline_->frames_emitted() : 0;
  j["bytes"] = in_.consumed();
  j["received"] = in_.received();
  j["time"] = last_time_;
  j["format"] = source_ ? ingest::log_format_name(format_) : "";
  j["done"] = done_ && !failed_;
  j["failed"] = failed_;
  if (failed_) j["error"] = error_;
  if (capped_) j["capped"] = options_.max_states;
  if (!in_.error().empty()) j["ended_early"] = in_.error();
  if (source_) {
    const auto& st = source_->stats();
    j["skipped"] = st.skipped;
    nlohmann::json errors = nlohmann::json::array();
    for (std::size_t i = 0; i < st.errors.size() && i < 3; ++i) errors.push_back(st.errors[i]);
    j["errors"] = std::move(errors);
  }
  // Replace, never throw, on text that is not UTF-8 (a reader's message may quote the log).
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace mc::wasm
