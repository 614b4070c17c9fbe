#include "proto/frame_codec.hpp"

#include "proto/range_coder.hpp"

namespace mc::proto {
namespace {

// The encoding side of codec_model.hpp's walk: reads each value, writes its
// residual.
struct EncodeIo {
  RangeEncoder enc;

  bool value(SignedModel& m, std::int32_t& v, std::int32_t pred, std::int32_t, std::int32_t, int zctx, int act,
             std::int32_t& r) {
    r = v - pred;
    encode_signed(enc, m, r, zctx, act);
    return true;
  }
  bool heading(SignedModel& m, std::int32_t& v, std::int32_t pred, int zctx, int act, std::int32_t& r) {
    r = detail::CodecModel::wrap_signed(static_cast<std::int64_t>(v) - pred);
    encode_signed(enc, m, r, zctx, act);
    return true;
  }
  bool flag(Prob& p, bool& b) {
    enc.encode_bit(p, b);
    return true;
  }
  void direct(std::uint32_t& v, int bits) { enc.encode_direct(v, bits); }
  // 5 bits of bit length L, then the L-1 bits below the leading one.
  void varbits(std::uint32_t& v) {
    int len = 0;
    while (len < 31 && (v >> len) != 0) ++len;
    enc.encode_direct(static_cast<std::uint32_t>(len), 5);
    if (len > 1) enc.encode_direct(v & ((1u << (len - 1)) - 1u), len - 1);
  }
};

}  // namespace

FrameEncoder::FrameEncoder(const SkeletonDef& skeleton, EncoderOptions options)
    : quant_(skeleton), options_(options) {
  if (options_.keyframe_interval < 1) options_.keyframe_interval = 1;
}

std::string FrameEncoder::encode(const PoseFrame& frame, bool& is_keyframe) {
  is_keyframe = !started_ || force_key_ || since_key_ >= options_.keyframe_interval ||
                frame.seq != last_seq_ + 1;
  QuantFrame q = quant_.quantize(frame);

  FrameHeader h;
  h.keyframe = is_keyframe;
  h.seq = frame.seq;
  h.time = frame.time;
  h.stoppage = frame.stoppage;
  h.substep = frame.substep;
  h.play_mode = static_cast<std::uint8_t>(frame.play_mode);
  h.score_left = frame.score_left;
  h.score_right = frame.score_right;
  h.server_time_ms = frame.server_time_ms;
  std::string out;
  out.reserve(kFrameHeaderSize + 512);
  write_header(h, out);

  EncodeIo io;
  if (is_keyframe) {
    model_.reset_for_keyframe();
    std::uint32_t fp = quant_.fingerprint();
    io.direct(fp, 32);
    detail::walk_keyframe(io, model_, quant_, q);
    since_key_ = 1;
  } else {
    detail::walk_delta(io, model_, quant_, q);
    ++since_key_;
  }
  model_.push(q);
  out += io.enc.finish();
  started_ = true;
  force_key_ = false;
  last_seq_ = frame.seq;
  return out;
}

}  // namespace mc::proto
