#include "proto/frame_codec.hpp"

#include <bit>

#include "proto/range_coder.hpp"

namespace mc::proto {
namespace {

// The encoding side of codec_model.hpp's walk: reads each value, writes its
// residual.
struct EncodeIo {
  RangeEncoder& enc;

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
  bool check(bool, const char*) { return true; }
  void direct(std::uint32_t& v, int bits) { enc.encode_direct(v, bits); }
  // 5 bits of bit length L, then the L-1 bits below the leading one.
  void varbits(std::uint32_t& v) {
    int len = 0;
    while (len < 31 && (v >> len) != 0) ++len;
    enc.encode_direct(static_cast<std::uint32_t>(len), 5);
    if (len > 1) enc.encode_direct(v & ((1u << (len - 1)) - 1u), len - 1);
  }
};

// Approximate bits of a residual under the signed-value code: enough to
// rank partner choices.
std::uint32_t cost_bits(std::int64_t r) {
  if (r == 0) return 1;
  const std::uint64_t m = static_cast<std::uint64_t>(r < 0 ? -r : r);
  // floor(log2 m) by one instruction, not a loop: learn_partners calls this
  // some 140,000 times a call (a quarter of the whole pipeline's time).
  const auto b = static_cast<std::uint32_t>(std::bit_width(m)) - 1;
  return 3 + 2 * b;
}

}  // namespace

void FrameEncoder::learn_partners() {
  const int dofs = quant_.dof_count();
  const auto n = static_cast<std::size_t>(kMaxDof);
  if (partner_cost_.empty()) partner_cost_.assign(n * n * 8, 0);
  // Each dof's eight predictions of the others, computed once per player.
  std::array<std::array<std::int64_t, 8>, kMaxDof> terms;
  for (std::size_t i = 0; i < kMaxPlayers; ++i) {
    const auto& r = model_.raw_angle_residual[i];
    for (int p = 0; p < dofs; ++p)
      for (std::size_t k = 0; k < 8; ++k)
        terms[static_cast<std::size_t>(p)][k] =
            detail::PartnerTable::term(detail::kPartnerCoef2[k], r[static_cast<std::size_t>(p)]);
    for (int d = 0; d < dofs; ++d) {
      const std::int64_t rd = r[static_cast<std::size_t>(d)];
      base_cost_[static_cast<std::size_t>(d)] += cost_bits(rd);
      for (int p = 0; p < d; ++p) {
        const std::int64_t rp = r[static_cast<std::size_t>(p)];
        std::uint32_t* c = &partner_cost_[(static_cast<std::size_t>(d) * n + static_cast<std::size_t>(p)) * 8];
        if (rp == 0) {  // every coefficient predicts 0
          const std::uint32_t b = cost_bits(rd);
          for (int k = 0; k < 8; ++k) c[k] += b;
          continue;
        }
        const auto& t = terms[static_cast<std::size_t>(p)];
        for (std::size_t k = 0; k < 8; ++k) c[k] += cost_bits(rd - t[k]);
      }
    }
  }
}

void FrameEncoder::choose_partners() {
  // Nothing learnt yet: every cost is 0, so no partner saves anything and
  // the table is the empty one (what choose_partners() gives for zeros).
  if (partner_cost_.empty()) {
    model_.partners = detail::PartnerTable{};
    return;
  }
  model_.partners = detail::choose_partners(base_cost_, partner_cost_, quant_.dof_count());
}

FrameEncoder::FrameEncoder(const SkeletonDef& skeleton, EncoderOptions options)
    : quant_(skeleton), options_(options), base_cost_(kMaxDof, 0) {
  if (options_.keyframe_interval < 1) options_.keyframe_interval = 1;
}

bool FrameEncoder::next_is_keyframe(const PoseFrame& frame) const {
  return !started_ || force_key_ || since_key_ >= options_.keyframe_interval || frame.seq != last_seq_ + 1;
}

FrameHeader header_of(const PoseFrame& frame, bool keyframe) {
  FrameHeader h;
  h.keyframe = keyframe;
  h.seq = frame.seq;
  h.time = frame.time;
  h.stoppage = frame.stoppage;
  h.substep = frame.substep;
  h.play_mode = static_cast<std::uint8_t>(frame.play_mode);
  h.score_left = frame.score_left;
  h.score_right = frame.score_right;
  h.server_time_ms = frame.server_time_ms;
  return h;
}

std::string FrameEncoder::encode(const PoseFrame& frame, bool& is_keyframe) {
  is_keyframe = next_is_keyframe(frame);
  const FrameHeader h = header_of(frame, is_keyframe);
  std::string out;
  out.reserve(kFrameHeaderSize + 512);
  write_header(h, out);
  RangeEncoder enc;
  encode_body(frame, is_keyframe, enc);
  out += enc.finish();
  return out;
}

void FrameEncoder::encode_body(const PoseFrame& frame, bool keyframe, RangeEncoder& enc) {
  QuantFrame q = quant_.quantize(frame);
  EncodeIo io{enc};
  if (keyframe) {
    model_.reset_for_keyframe();
    choose_partners();
    std::uint32_t fp = quant_.fingerprint();
    io.direct(fp, 32);
    detail::walk_keyframe(io, model_, quant_, q);
    since_key_ = 1;
  } else {
    detail::walk_delta(io, model_, quant_, q, frame.substep);
    if (since_key_ % 4 == 1) learn_partners();  // every 4th delta: a quarter of the cost, as good a sample
    ++since_key_;
  }
  model_.push(q);
  started_ = true;
  force_key_ = false;
  last_seq_ = frame.seq;
}

}  // namespace mc::proto
