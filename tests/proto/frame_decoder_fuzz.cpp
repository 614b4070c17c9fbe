// libFuzzer target for everything in proto/ that reads untrusted bytes: the
// pose-frame decoder (as a raw frame, and as the body of a delta/keyframe
// after a valid keyframe so the fuzzer reaches deep into the walk), control
// messages, the hello, and the recording records (with their frame streams
// and binary control messages). Must never crash, hang or
// read out of bounds (ASan/UBSan); refusing is fine.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "proto/control_binary.hpp"
#include "proto/control_messages.hpp"
#include "proto/frame_codec.hpp"
#include "proto/frame_stream.hpp"
#include "proto/hello.hpp"
#include "proto/recording.hpp"
#include "tests/proto/support/synthetic.hpp"

namespace {

// Built once, not per input (the decoders' models are large, and decoding
// the keyframe every time made this target run at ~600 inputs/s): each
// input starts from a copy of a decoder in the state it needs.
struct Fixture {
  mc::SkeletonDef skeleton = mc::proto::testing::humanoid_skeleton();
  std::vector<std::string> frames;  // a keyframe and two deltas
  std::optional<mc::proto::FrameDecoder> cold, after_key, after_delta;
  std::string refused;  // a frame every decoder refuses at once (play mode 255): back to "no keyframe yet"
  Fixture() {
    mc::proto::FrameEncoder enc(skeleton);
    for (const auto& f : mc::proto::testing::scripted_frames(skeleton, 3)) {
      bool key = false;
      frames.push_back(enc.encode(f, key));
    }
    mc::PoseFrame out;
    std::string error;
    cold.emplace(skeleton);
    after_key.emplace(skeleton);
    if (!after_key->decode(frames[0], out, error)) std::abort();
    after_delta = after_key;
    if (!after_delta->decode(frames[1], out, error)) std::abort();
    refused = frames[0];
    refused[15] = static_cast<char>(0xff);  // header byte 15: play mode
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Fixture fx;
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::string error;
  mc::PoseFrame out;

  // A decoder's state matters only to a delta that follows its base (seq =
  // last + 1): a keyframe resets all a delta reads, and any other delta is
  // refused. So one scratch decoder serves every other case, and a warm
  // prototype (80 KB) is copied only where a delta would use it.
  static mc::proto::FrameDecoder scratch = *fx.cold;
  static mc::proto::FrameDecoder warm = *fx.cold;
  const auto make_cold = [&] { scratch.decode(fx.refused, out, error); };  // history = 0
  {  // 1. the bytes as a frame, cold and after a keyframe + a delta
    make_cold();
    scratch.decode(input, out, error);
    mc::proto::FrameHeader h;
    if (mc::proto::peek_header(input, h, error) && !h.keyframe && h.seq == 2) {
      warm = *fx.after_delta;
      warm.decode(input, out, error);
    }
  }
  {  // 2. the bytes as the body of a delta (seq 2, after its base) and of a keyframe
    warm = *fx.after_delta;
    warm.decode(fx.frames[2].substr(0, mc::proto::kFrameHeaderSize) + input, out, error);
    scratch.decode(fx.frames[0].substr(0, mc::proto::kFrameHeaderSize) + input, out, error);
  }
  {  // 3. JSON control messages and hello
    mc::proto::ControlMessage m;
    mc::proto::control_from_json(input, m, error);
    mc::proto::Hello h;
    if (mc::proto::hello_from_json(input, h, error)) {
      mc::proto::FrameDecoder other(h.skeleton);  // any skeleton a hello can carry
      other.decode(fx.frames[0], out, error);
    }
  }
  {  // 4. recording records, chunks and index
    namespace rec = mc::proto::rec;
    rec::RecordView v;
    rec::parse_record(input, v, error);
    rec::ChunkInfo info;
    std::vector<rec::ChunkEntry> entries;
    std::string_view frame_stream;
    rec::parse_chunk(input, info, entries, error, rec::kFormatMajor, &frame_stream);  // frame stream
    rec::parse_chunk(input, info, entries, error, 2);                  // control text deflated
    rec::parse_chunk(input, info, entries, error, rec::kOldestMajor);  // control text inline
    std::vector<rec::ChunkInfo> chunks;
    rec::parse_index(input, chunks, error);
    rec::FileHeader fh;
    rec::parse_file_header(input, fh, error);
    std::string text;
    rec::expand_control(input, text);  // binary control messages
  }
  {  // 5. the bytes as a recording chunk's frame stream, cold and after a keyframe
    for (int after_key = 0; after_key < 2; ++after_key) {
      if (after_key) {
        warm = *fx.after_key;
      } else {
        make_cold();
      }
      mc::proto::FrameStreamDecoder sd(after_key ? warm : scratch, input, {1, 0, 0, 1}, 8);
      for (int k = 0; k < 8 && sd.next(out, error); ++k) {
      }
    }
  }
  return 0;
}
