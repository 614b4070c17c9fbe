// The recording format, in memory (no I/O: server/record/ does the file
// work). SPEC.md section 6 is the normative description.
//
// A recording is the stream itself, cut into records that a reader can
// check one by one, so that a file cut anywhere (crash, SIGKILL) is still
// readable up to its last complete record:
//
//   file header (16 B) | hello record | chunk record | chunk record | ...
//   | index record | trailer (16 B)          <- only after a clean close
//
//   record  = u32 payload length | u8 type | payload | u32 CRC-32(type, payload)
//   hello   = the hello JSON (format 3: deflated)
//   chunk   = the frames (and control messages, in stream order) of at
//             most a second; the control messages' text deflated together
//             (format 2; format 1 kept it inline, and is still read); the
//             frames as one range-coded stream (format 3, frame_stream.hpp;
//             formats 1 and 2 kept each frame's own bytes, still read)
//   index   = where each chunk starts and its first frame's seq/time
//   trailer = "MCINDEX\0" | u64 offset of the index record
//
// All integers little-endian.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "proto/frame_header.hpp"

namespace mc::proto::rec {

inline constexpr std::uint8_t kFormatMajor = 3;   // what writers write
inline constexpr std::uint8_t kOldestMajor = 1;   // readers read kOldestMajor..kFormatMajor, refuse others
inline constexpr std::uint8_t kFormatMinor = 0;
inline constexpr std::size_t kFileHeaderSize = 16;
inline constexpr std::size_t kRecordOverhead = 9;   // length + type + CRC
inline constexpr std::size_t kTrailerSize = 16;
// A record longer than this is corruption (a chunk of 1 s is ~10 KB).
inline constexpr std::uint32_t kMaxRecordPayload = 64u << 20;
// More frames than this in one chunk is corruption (a writer cuts a chunk
// every second; this is an hour at 20 Hz): a reader allocates nothing for more.
inline constexpr std::uint32_t kMaxChunkFrames = 72000;

enum class RecordType : std::uint8_t { Hello = 1, Chunk = 2, Index = 3 };

struct FileHeader {
  std::uint8_t major = kFormatMajor, minor = kFormatMinor;
  std::uint64_t created_unix_ms = 0;
};
std::string encode_file_header(const FileHeader& header);
// False + error for a short input, a wrong magic or a major outside
// kOldestMajor..kFormatMajor.
bool parse_file_header(std::string_view bytes, FileHeader& out, std::string& error);

std::uint32_t crc32(std::string_view bytes, std::uint32_t crc = 0);

std::string encode_record(RecordType type, std::string_view payload);

enum class RecordStatus { Ok, Truncated, Corrupt };
struct RecordView {
  RecordType type = RecordType::Hello;
  std::string_view payload;
  std::size_t total_size = 0;  // bytes the record occupies, overhead included
};
// Parses the record at the start of `bytes`. Truncated: `bytes` ends inside
// it (a crash while writing). Corrupt: bad length, unknown type or CRC.
RecordStatus parse_record(std::string_view bytes, RecordView& out, std::string& error);
// How many bytes the record at the start of `bytes` needs in total, from its
// length field alone (0 when fewer than 4 bytes are given).
std::size_t record_size_hint(std::string_view bytes);

// What the index knows about one chunk.
struct ChunkInfo {
  std::uint64_t offset = 0;       // file offset of the chunk record
  std::uint32_t first_seq = 0;
  int first_time = 0;             // simulation cycle of the first frame
  int first_stoppage = 0;
  std::uint8_t first_substep = 0;
  bool starts_with_keyframe = false;
  std::uint32_t frame_count = 0;
};

struct ChunkEntry {
  // Frame: an encoded pose frame (header restored) in `bytes`. Control: a
  // JSON control message in `bytes`. StreamFrame: the next frame of the
  // chunk's frame stream (format 3; `bytes` empty, see frame_stream.hpp).
  enum class Kind : std::uint8_t { Frame = 1, Control = 2, StreamFrame = 3 } kind = Kind::Frame;
  std::string bytes;
};

// Collects one chunk. Frames and control messages keep their order. The
// first frame of a chunk is stored whole; each later one with its 26-byte
// header reduced to what changed since the previous frame (usually 4
// bytes: the frames of a chunk count up by one, 50 ms apart), and restored
// byte for byte by parse_chunk.
// Builds a chunk of the current format (kFormatMajor).
class ChunkBuilder {
 public:
  // `frame` must be a valid encoded frame (its header is read); false + error otherwise.
  bool add_frame(std::string_view frame, std::string& error);
  // A frame that went into the chunk's frame stream (FrameStreamEncoder),
  // with the header the stream coded. RecordingWriter puts all of a
  // chunk's frames one way or the other; parse_chunk reads either.
  void add_stream_frame(const FrameHeader& header);
  void add_control(std::string_view json_text);
  bool empty() const { return entries_ == 0 && stream_run_ == 0; }
  std::uint32_t frame_count() const { return info_.frame_count; }
  // The chunk record (offset in `info` is left to the caller), and a reset.
  // `frame_stream`: the stream's bytes when stream frames were added.
  std::string finish(ChunkInfo& info, std::string_view frame_stream = {});

 private:
  void add(ChunkEntry::Kind kind, std::string_view bytes);
  void note_first(const FrameHeader& h);
  void end_stream_run();
  std::string body_;
  std::string controls_;  // the control messages' text, deflated by finish()
  std::uint32_t entries_ = 0;
  ChunkInfo info_;
  std::string last_header_;  // the previous frame's header in this chunk, "" if none
  std::uint32_t stream_run_ = 0;  // stream frames since the last entry written
};

// Parses a chunk payload of a file of format `major`; false + error when it
// is malformed. `frame_stream` (format 3) receives the bytes of the chunk's
// frame stream, a view into `payload`, empty when it has no stream frames.
bool parse_chunk(std::string_view payload, ChunkInfo& info, std::vector<ChunkEntry>& entries, std::string& error,
                 std::uint8_t major = kFormatMajor, std::string_view* frame_stream = nullptr);

std::string encode_index(const std::vector<ChunkInfo>& chunks);  // the index record (current format)
bool parse_index(std::string_view payload, std::vector<ChunkInfo>& out, std::string& error,
                 std::uint8_t major = kFormatMajor);
// The hello record's payload (current format: the JSON text deflated), and
// the JSON text back from a file of format `major`.
std::string encode_hello(std::string_view json_text);
bool parse_hello(std::string_view payload, std::string& json_text, std::string& error,
                 std::uint8_t major = kFormatMajor);
std::string encode_trailer(std::uint64_t index_offset);
// False when the last 16 bytes of a file are not a trailer.
bool parse_trailer(std::string_view last16, std::uint64_t& index_offset);

// The chunk to start decoding from to reach simulation time `time` (and
// `stoppage`): the last chunk starting with a keyframe whose first frame is
// at or before it; 0 when the time is before the first chunk or `chunks`
// is empty. `chunks` in file order; chunks of control messages only (frame
// count 0, no time) are looked past.
std::size_t find_chunk(const std::vector<ChunkInfo>& chunks, int time, int stoppage = 0);

}  // namespace mc::proto::rec
