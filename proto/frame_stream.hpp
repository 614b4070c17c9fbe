// A recording chunk's pose frames as one range-coded stream (recording
// format 3, SPEC.md section 6): each frame's header coded against the
// previous one, then its body with the frame codec, all through one range
// coder flushed once per chunk.
//
// Why: a frame on the wire is self-delimiting (26-byte header, its own
// coder, a 4-byte flush). In a file those ~10 bytes a frame, 20 times a
// second, were 4 % of a full game; in the stream a header costs a few bits
// (seq +1, time +0/+1, 50 ms later) and the flush is paid once a chunk.
// The frames decoded are the ones encoded, field for field.
//
// The codec model (FrameEncoder/FrameDecoder) carries on from chunk to
// chunk as it does from frame to frame; a chunk that starts with a keyframe
// can be decoded on its own, which is what seeking needs.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "proto/frame_codec.hpp"
#include "proto/range_coder.hpp"
#include "proto/residual_coder.hpp"

namespace mc::proto {

// The first frame's seq, time, stoppage and substep, which the chunk's own
// header already holds: the stream codes its first frame against them.
struct StreamStart {
  std::uint32_t seq = 0;
  int time = 0;
  int stoppage = 0;
  std::uint8_t substep = 0;
};

namespace detail {
// Adaptive contexts of the headers in one stream.
struct HeaderModel {
  Prob keyframe = kProbInit, seq_next = kProbInit, substep_flip = kProbInit, server_time_whole = kProbInit,
       mode_changed = kProbInit;
  SignedModel time, stoppage, server_time;
  FrameHeader prev;                 // the previous frame's header
  std::int64_t prev_interval = 50;  // its server-time step, ms
  bool first = true;                // no frame coded yet (server time, play mode and score sent whole)
  explicit HeaderModel(const StreamStart& s);
};
}  // namespace detail

class FrameStreamEncoder {
 public:
  // `encoder` keeps its model across chunks; it must outlive this object.
  explicit FrameStreamEncoder(FrameEncoder& encoder) : encoder_(encoder) {}

  // Codes one frame; returns its header (keyframe as the encoder chose).
  // Substep is coded in one bit: it must be 0 or 1 (RecordingWriter skips
  // other frames).
  FrameHeader add(const PoseFrame& frame);
  std::uint32_t frame_count() const { return frames_; }
  // The stream's bytes ("" when no frame was added), and a fresh stream for
  // the next chunk.
  std::string finish();

 private:
  FrameEncoder& encoder_;
  RangeEncoder enc_;
  detail::HeaderModel model_{StreamStart{}};
  std::uint32_t frames_ = 0;
};

class FrameStreamDecoder {
 public:
  // `bytes` must stay valid while frames are read; `frame_count` is how many
  // frames the chunk says the stream holds.
  FrameStreamDecoder(FrameDecoder& decoder, std::string_view bytes, const StreamStart& start,
                     std::uint32_t frame_count);

  // The next frame. False + error when the stream is corrupt or truncated,
  // when the frame does not decode (FrameDecoder::decode_body), or when the
  // last frame leaves bytes unread; the rest of the stream is then unusable.
  bool next(PoseFrame& out, std::string& error);

 private:
  FrameDecoder& decoder_;
  std::string_view bytes_;
  RangeDecoder dec_;
  detail::HeaderModel model_;
  std::uint32_t left_;
};

}  // namespace mc::proto
