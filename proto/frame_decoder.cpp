#include "proto/frame_codec.hpp"

#include "proto/range_coder.hpp"

namespace mc::proto {
namespace {

// The decoding side of codec_model.hpp's walk: reads each residual, adds
// the prediction, and refuses values outside their range.
struct DecodeIo {
  RangeDecoder& dec;
  std::string& error;

  bool corrupt(const char* what) {
    error = dec.overrun() ? std::string("pose frame truncated")
                          : std::string("corrupt pose frame: ") + what + " out of range";
    return false;
  }
  // A body that ran out is refused whatever follows (SPEC.md 4.2): the walk
  // stops at the first value read past the end instead of walking every
  // player on zero bytes.
  bool value(SignedModel& m, std::int32_t& v, std::int32_t pred, std::int32_t lo, std::int32_t hi, int zctx, int act,
             std::int32_t& r) {
    const std::int64_t res = decode_signed(dec, m, zctx, act);
    const std::int64_t val = pred + res;
    if (dec.overrun() || val < lo || val > hi) return corrupt("value");
    v = static_cast<std::int32_t>(val);
    r = static_cast<std::int32_t>(res);
    return true;
  }
  bool heading(SignedModel& m, std::int32_t& v, std::int32_t pred, int zctx, int act, std::int32_t& r) {
    const std::int64_t res = decode_signed(dec, m, zctx, act);
    if (dec.overrun() || res < -kHeadingSteps / 2 || res >= kHeadingSteps / 2) return corrupt("heading");
    v = detail::CodecModel::wrap(pred + res);
    r = static_cast<std::int32_t>(res);
    return true;
  }
  bool flag(Prob& p, bool& b) {
    b = dec.decode_bit(p);
    return true;
  }
  bool check(bool ok, const char* what) { return ok || corrupt(what); }
  void direct(std::uint32_t& v, int bits) { v = dec.decode_direct(bits); }
  void varbits(std::uint32_t& v) {
    const std::uint32_t len = dec.decode_direct(5);
    v = len == 0 ? 0u : len == 1 ? 1u : (1u << (len - 1)) | dec.decode_direct(static_cast<int>(len - 1));
  }
};

}  // namespace

FrameDecoder::FrameDecoder(const SkeletonDef& skeleton) : quant_(skeleton) {}

bool FrameDecoder::decode(std::string_view bytes, PoseFrame& out, std::string& error) {
  FrameHeader h;
  if (!peek_header(bytes, h, error)) return false;
  const std::string_view body = bytes.substr(kFrameHeaderSize);
  RangeDecoder dec(body);
  if (!decode_body(h, dec, out, error)) return false;
  if (h.minor == kProtocolMinor && dec.consumed() != body.size()) {
    // A newer minor version may append data; our own version must not.
    error = "corrupt pose frame " + std::to_string(h.seq) + ": " + std::to_string(body.size() - dec.consumed()) +
            " unexpected trailing bytes";
    model_.history = 0;  // the frame is refused: wait for a keyframe
    return false;
  }
  return true;
}

bool FrameDecoder::decode_body(const FrameHeader& h, RangeDecoder& dec, PoseFrame& out, std::string& error) {
  if (h.play_mode >= kPlayModeCount) {
    error = "corrupt pose frame: play mode " + std::to_string(h.play_mode) + " is not defined";
    model_.history = 0;
    return false;
  }
  if (!h.keyframe) {
    if (model_.history == 0) {
      error = "delta frame " + std::to_string(h.seq) + " without its base: waiting for a keyframe";
      return false;
    }
    if (h.seq != last_seq_ + 1) {
      error = "gap before delta frame " + std::to_string(h.seq) + " (last frame was " +
              std::to_string(last_seq_) + "): waiting for a keyframe";
      model_.history = 0;
      return false;
    }
  }

  DecodeIo io{dec, error};
  // Decoded in place: a refused frame leaves the model half-updated, but it
  // also sets history = 0, and the only frame accepted next is a keyframe,
  // which resets every part of the model that a delta reads.
  detail::CodecModel& next = model_;
  QuantFrame q;
  bool ok;
  if (h.keyframe) {
    next.reset_for_keyframe();
    std::uint32_t fp = 0;
    io.direct(fp, 32);
    ok = true;
    if (!io.dec.overrun() && fp != quant_.fingerprint()) {
      error = "keyframe was encoded for a different skeleton (fingerprint " + std::to_string(fp) + ", expected " +
              std::to_string(quant_.fingerprint()) + ")";
      ok = false;
    }
    ok = ok && detail::walk_keyframe(io, next, quant_, q);
  } else {
    ok = detail::walk_delta(io, next, quant_, q, h.substep);
  }
  if (ok && io.dec.overrun()) {
    error = std::string(h.keyframe ? "keyframe " : "delta frame ") + std::to_string(h.seq) + " truncated";
    ok = false;
  }
  if (!ok) {
    model_.history = 0;  // the stream state is unknown now: wait for a keyframe
    return false;
  }
  next.push(q);
  last_seq_ = h.seq;
  out.seq = h.seq;
  out.time = h.time;
  out.stoppage = h.stoppage;
  out.substep = h.substep;
  out.server_time_ms = h.server_time_ms;
  out.play_mode = static_cast<PlayMode>(h.play_mode);
  out.score_left = h.score_left;
  out.score_right = h.score_right;
  quant_.dequantize(q, out);
  return true;
}

}  // namespace mc::proto
