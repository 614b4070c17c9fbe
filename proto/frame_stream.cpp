#include "proto/frame_stream.hpp"

#include <limits>

namespace mc::proto {
namespace detail {

HeaderModel::HeaderModel(const StreamStart& s) {
  // The first frame is coded against a made-up predecessor that says what
  // the chunk header says: so seq, time, stoppage and substep cost a bit each.
  prev.seq = s.seq - 1;
  prev.time = s.time;
  prev.stoppage = s.stoppage;
  prev.substep = static_cast<std::uint8_t>(s.substep ^ 1u);
}

}  // namespace detail
namespace {

// A server-time step that changes by more than this (a clock jump, a new
// source) is sent whole: the signed-value code holds 32 bits at most.
constexpr std::int64_t kServerTimeJump = std::int64_t{1} << 30;

// One walk of a header for both sides (SPEC.md section 6, "Frame stream"),
// so that the encoder and decoder cannot disagree on an order or a context.
// `Io` reads `h` when encoding and writes it when decoding.
template <class Io>
bool walk_header(Io& io, detail::HeaderModel& m, FrameHeader& h) {
  const FrameHeader& p = m.prev;
  bool key = h.keyframe;
  io.flag(m.keyframe, key);
  h.keyframe = key;

  bool seq_next = h.seq == p.seq + 1;
  io.flag(m.seq_next, seq_next);
  std::uint32_t seq = seq_next ? p.seq + 1 : h.seq;
  if (!seq_next) io.direct(seq, 32);
  h.seq = seq;

  bool flip = h.substep != p.substep;
  io.flag(m.substep_flip, flip);
  h.substep = static_cast<std::uint8_t>(flip ? p.substep ^ 1u : p.substep);

  std::int64_t dt = static_cast<std::int64_t>(h.time) - p.time;
  if (!io.value(m.time, dt)) return false;
  const std::int64_t time = p.time + dt;
  if (!io.check(time >= std::numeric_limits<std::int32_t>::min() && time <= std::numeric_limits<std::int32_t>::max(),
                "time"))
    return false;
  h.time = static_cast<int>(time);

  std::int64_t ds = static_cast<std::int64_t>(h.stoppage) - p.stoppage;
  if (!io.value(m.stoppage, ds)) return false;
  const std::int64_t stoppage = p.stoppage + ds;
  if (!io.check(stoppage >= 0 && stoppage <= 65535, "stoppage")) return false;
  h.stoppage = static_cast<int>(stoppage);

  // Server time: whole in the first frame and after a jump (a bit says
  // which), else the change of its step since the previous frame.
  bool whole = m.first;
  std::int64_t change = 0;
  if (!m.first) {
    change = static_cast<std::int64_t>(h.server_time_ms - p.server_time_ms) - m.prev_interval;
    whole = change < -kServerTimeJump || change > kServerTimeJump;
    io.flag(m.server_time_whole, whole);
  }
  if (whole) {
    std::uint32_t lo = static_cast<std::uint32_t>(h.server_time_ms), hi = static_cast<std::uint32_t>(h.server_time_ms >> 32);
    io.direct(lo, 32);
    io.direct(hi, 32);
    h.server_time_ms = (static_cast<std::uint64_t>(hi) << 32) | lo;
  } else {
    if (!io.value(m.server_time, change)) return false;
    if (!io.check(change >= -kServerTimeJump && change <= kServerTimeJump, "server time")) return false;
    const std::int64_t interval = m.prev_interval + change;
    h.server_time_ms = p.server_time_ms + static_cast<std::uint64_t>(interval);
    m.prev_interval = interval;
  }

  bool mode = m.first || h.play_mode != p.play_mode || h.score_left != p.score_left || h.score_right != p.score_right;
  if (!m.first) io.flag(m.mode_changed, mode);
  if (mode) {
    std::uint32_t pm = h.play_mode, sl = h.score_left, sr = h.score_right;
    io.direct(pm, 8);
    io.direct(sl, 8);
    io.direct(sr, 8);
    h.play_mode = static_cast<std::uint8_t>(pm);
    h.score_left = static_cast<std::uint8_t>(sl);
    h.score_right = static_cast<std::uint8_t>(sr);
  } else {
    h.play_mode = p.play_mode;
    h.score_left = p.score_left;
    h.score_right = p.score_right;
  }
  h.major = kProtocolMajor;
  h.minor = kProtocolMinor;
  m.prev = h;
  m.first = false;
  return true;
}

struct HeaderEncodeIo {
  RangeEncoder& enc;
  void flag(Prob& p, bool& b) { enc.encode_bit(p, b); }
  void direct(std::uint32_t& v, int bits) { enc.encode_direct(v, bits); }
  bool value(SignedModel& m, std::int64_t& v) {
    encode_signed(enc, m, v, 0, 0);
    return true;
  }
  bool check(bool, const char*) { return true; }
};

struct HeaderDecodeIo {
  RangeDecoder& dec;
  std::string& error;
  void flag(Prob& p, bool& b) { b = dec.decode_bit(p); }
  void direct(std::uint32_t& v, int bits) { v = dec.decode_direct(bits); }
  bool value(SignedModel& m, std::int64_t& v) {
    v = decode_signed(dec, m, 0, 0);
    return true;
  }
  bool check(bool ok, const char* what) {
    if (!ok) error = std::string("corrupt frame stream: ") + what + " out of range";
    return ok;
  }
};

}  // namespace

FrameHeader FrameStreamEncoder::add(const PoseFrame& frame) {
  if (frames_ == 0) model_ = detail::HeaderModel(StreamStart{frame.seq, frame.time, frame.stoppage, frame.substep});
  FrameHeader h = header_of(frame, encoder_.next_is_keyframe(frame));
  HeaderEncodeIo io{enc_};
  walk_header(io, model_, h);
  encoder_.encode_body(frame, h.keyframe, enc_);
  ++frames_;
  return h;
}

std::string FrameStreamEncoder::finish() {
  std::string out = frames_ > 0 ? enc_.finish() : std::string();
  enc_ = RangeEncoder{};
  frames_ = 0;
  return out;
}

FrameStreamDecoder::FrameStreamDecoder(FrameDecoder& decoder, std::string_view bytes, const StreamStart& start,
                                       std::uint32_t frame_count)
    : decoder_(decoder), bytes_(bytes), dec_(bytes), model_(start), left_(frame_count) {}

bool FrameStreamDecoder::next(PoseFrame& out, std::string& error) {
  if (left_ == 0) {
    error = "corrupt frame stream: more frames asked for than it holds";
    return false;
  }
  FrameHeader h;
  HeaderDecodeIo io{dec_, error};
  if (!walk_header(io, model_, h)) return false;
  if (dec_.overrun()) {
    error = "frame stream truncated";
    return false;
  }
  if (!decoder_.decode_body(h, dec_, out, error)) return false;
  if (--left_ == 0 && dec_.consumed() != bytes_.size()) {
    error = "corrupt frame stream: " + std::to_string(bytes_.size() - dec_.consumed()) + " bytes after its last frame";
    left_ = 0;
    return false;
  }
  return true;
}

}  // namespace mc::proto
