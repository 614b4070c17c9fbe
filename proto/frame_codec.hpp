// Pose-frame encoder and decoder (SPEC.md is the normative description).
//
// A frame is a 26-byte header (proto/frame_header.hpp) and a body coded
// with an adaptive binary range coder. Keyframes are self-contained; a delta
// frame codes each quantized value as the residual of a prediction from the
// two previous frames (hold or linear, whichever has served that kind of
// value better), minus a share of a partner dof's residual (mirrored limbs),
// in contexts chosen by how much the same value moved last time
// (codec_model.hpp). Costs on a real full game: SPEC.md and the benchmark
// tests/proto/bench/pose_stream_bench.cpp.
// The relay encodes each frame once and sends the same bytes to everyone.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "proto/codec_model.hpp"
#include "proto/frame_header.hpp"
#include "proto/pose_frame.hpp"
#include "proto/quantizer.hpp"
#include "proto/range_coder.hpp"
#include "proto/skeleton.hpp"

namespace mc::proto {

struct EncoderOptions {
  // Frames between keyframes: 20 = 1 s at 20 Hz. A late joiner or a client
  // that skipped frames waits at most this long for a picture.
  int keyframe_interval = 20;
};

// The header fields of `frame` (magic and versions: this build's).
FrameHeader header_of(const PoseFrame& frame, bool keyframe);

class FrameEncoder {
 public:
  explicit FrameEncoder(const SkeletonDef& skeleton, EncoderOptions options = {});

  // Encodes one frame (including frame.server_time_ms; see also
  // stamp_server_time). It is a keyframe when it is the first frame, when
  // keyframe_interval frames have passed since the last one, after
  // force_keyframe(), or when frame.seq is not the previous seq + 1 (a delta
  // must follow its base directly).
  std::string encode(const PoseFrame& frame, bool& is_keyframe);
  void force_keyframe() { force_key_ = true; }
  // Whether the next encode() or encode_body() of `frame` makes a keyframe.
  bool next_is_keyframe(const PoseFrame& frame) const;
  // The body alone (what encode() puts after the header) onto an outside
  // range coder, so that several frames share one coder and one flush (the
  // recording's frame stream, frame_stream.hpp). `keyframe` must be
  // next_is_keyframe(frame).
  void encode_body(const PoseFrame& frame, bool keyframe, RangeEncoder& enc);

  const Quantizer& quantizer() const { return quant_; }

 private:
  void learn_partners();
  void choose_partners();

  Quantizer quant_;
  EncoderOptions options_;
  detail::CodecModel model_;
  // Estimated bits of each dof's residuals with each (partner, coefficient),
  // [dof][partner][coef], and without a partner: for choose_partners().
  // partner_cost_ (128 KB) stays empty until the first delta is learnt
  // from: an encoder that sends keyframes only (a replay paused or seeking)
  // never needs it, and every replay spectator has an encoder of its own.
  std::vector<std::uint32_t> partner_cost_;
  std::vector<std::uint64_t> base_cost_;
  bool started_ = false;
  bool force_key_ = false;
  int since_key_ = 0;
  std::uint32_t last_seq_ = 0;
};

class FrameDecoder {
 public:
  explicit FrameDecoder(const SkeletonDef& skeleton);

  // Decodes one frame into `out` (every field of `out` is written). False,
  // with a one-line `error`, when the bytes are truncated or corrupt, the
  // major version is unknown, the keyframe was made for another skeleton,
  // or a delta arrives without its base (no keyframe yet, or a seq gap).
  // After a false return the decoder waits for the next keyframe; `out` is
  // then unspecified. Never reads outside `bytes`.
  bool decode(std::string_view bytes, PoseFrame& out, std::string& error);

  // The body of the frame whose header is `h`, from an outside range
  // decoder (the counterpart of FrameEncoder::encode_body); the same
  // checks and errors as decode(), except the trailing-bytes check, which
  // is the caller's.
  bool decode_body(const FrameHeader& h, RangeDecoder& dec, PoseFrame& out, std::string& error);

  // True once a keyframe was decoded and no gap or error happened since.
  bool synced() const { return model_.history > 0; }
  // Forgets the stream, as a new decoder would: the next frame accepted is
  // a keyframe, which resets every part of the model a delta reads (the
  // state any refused frame leaves). Cheaper than a new decoder (its models
  // are tens of KB), e.g. for a recording reader's every seek.
  void reset() { model_.history = 0; }
  const Quantizer& quantizer() const { return quant_; }

 private:
  Quantizer quant_;
  detail::CodecModel model_;
  std::uint32_t last_seq_ = 0;
};

}  // namespace mc::proto
