// libFuzzer target for everything in proto/ that reads untrusted bytes: the
// pose-frame decoder (as a raw frame, and as the body of a delta/keyframe
// after a valid keyframe so the fuzzer reaches deep into the walk), control
// messages, the hello, and the recording records (with their frame streams
// and binary control messages). Must never crash, hang or
// read out of bounds (ASan/UBSan); refusing is fine.
#include <cstddef>
#include <cstdint>
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

struct Fixture {
  mc::SkeletonDef skeleton = mc::proto::testing::humanoid_skeleton();
  std::vector<std::string> frames;  // a keyframe and two deltas
  Fixture() {
    mc::proto::FrameEncoder enc(skeleton);
    for (const auto& f : mc::proto::testing::scripted_frames(skeleton, 3)) {
      bool key = false;
      frames.push_back(enc.encode(f, key));
    }
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Fixture fx;
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::string error;
  mc::PoseFrame out;

  {  // 1. the bytes as a frame, cold and after a keyframe + a delta
    mc::proto::FrameDecoder cold(fx.skeleton);
    cold.decode(input, out, error);
    mc::proto::FrameDecoder warm(fx.skeleton);
    warm.decode(fx.frames[0], out, error);
    warm.decode(fx.frames[1], out, error);
    warm.decode(input, out, error);
  }
  {  // 2. the bytes as the body of a delta (seq 2) and of a keyframe
    for (std::size_t which : {std::size_t{2}, std::size_t{0}}) {
      std::string frame = fx.frames[which].substr(0, mc::proto::kFrameHeaderSize) + input;
      mc::proto::FrameDecoder dec(fx.skeleton);
      dec.decode(fx.frames[0], out, error);
      dec.decode(fx.frames[1], out, error);
      dec.decode(frame, out, error);
    }
  }
  {  // 3. JSON control messages and hello
    mc::proto::ControlMessage m;
    mc::proto::control_from_json(input, m, error);
    mc::proto::Hello h;
    if (mc::proto::hello_from_json(input, h, error)) {
      mc::proto::FrameDecoder dec(h.skeleton);  // any skeleton a hello can carry
      dec.decode(fx.frames[0], out, error);
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
    for (int warm = 0; warm < 2; ++warm) {
      mc::proto::FrameDecoder dec(fx.skeleton);
      if (warm) dec.decode(fx.frames[0], out, error);
      mc::proto::FrameStreamDecoder sd(dec, input, {1, 0, 0, 1}, 8);
      for (int k = 0; k < 8 && sd.next(out, error); ++k) {
      }
    }
  }
  return 0;
}
