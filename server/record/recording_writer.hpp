// Writes a recording file (proto/recording.hpp) while the stream runs.
//
// Safety: the file is only ever appended to. Frames are collected into a
// chunk in memory and each chunk is written with one write() when the next
// keyframe arrives or as soon as it holds max_chunk_frames, then
// fdatasync'ed if `sync` is set. A crash or SIGKILL therefore loses at most
// the frames of the chunk being collected (max_chunk_frames - 1: 0.95 s by
// default) and never touches bytes already written; the reader drops a
// half-written last record. A write
// that fails (a full disk, a file-size limit) is cut back off the file, so
// that what is left is whole records.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <memory>

#include "proto/frame_codec.hpp"
#include "proto/frame_stream.hpp"
#include "proto/recording.hpp"

namespace mc::record {

struct WriterOptions {
  // Write a chunk after this many frames even if no keyframe came (a chunk
  // is the most a crash can lose; 20 frames = 1 s at 20 Hz).
  std::uint32_t max_chunk_frames = 20;
  // fdatasync after each chunk, so that a power cut also loses at most one
  // chunk. SIGKILL-safety does not need it (the page cache survives).
  bool sync = true;
  // Frames between keyframes in the file. 0 stores the stream's frames
  // byte for byte. N > 0 transcodes them (decode, re-encode with a keyframe
  // every N frames) into each chunk's frame stream (format 3): the same
  // quantized values, so the same decoded poses, with fewer keyframes. On
  // the benchmark game (frames only): 100 2.99 MB, 200 2.95 MB. A seek
  // decodes at most N + 20 frames (~25 us each): at 200 it took 2.4-2.6 ms
  // mean, 5.4 ms worst of 200 seeks on a quiet machine, under the 10 ms
  // target with room for a loaded one.
  int keyframe_interval = 200;
  // Creation time written in the file header (Unix ms); 0 = now. Fixed only
  // to make reproducible files (the golden recording).
  std::uint64_t created_unix_ms = 0;
};

class RecordingWriter {
 public:
  RecordingWriter() = default;
  ~RecordingWriter();  // close()s
  RecordingWriter(const RecordingWriter&) = delete;
  RecordingWriter& operator=(const RecordingWriter&) = delete;

  // Creates (truncates) `path` and writes the file header and the hello
  // (JSON text, proto/hello.hpp). False + error on any I/O failure.
  bool open(const std::string& path, std::string_view hello_json, std::string& error,
            WriterOptions options = {});
  // Appends one encoded pose frame, as sent to spectators. When
  // transcoding, a frame the stream decoder refuses (a delta after a gap)
  // is skipped and counted, as a spectator would skip it.
  bool add_frame(std::string_view frame, std::string& error);
  std::uint64_t skipped_frames() const { return skipped_; }
  // Appends one JSON control message (event or metadata) in stream order.
  bool add_control(std::string_view json_text, std::string& error);
  // Writes the pending chunk now (for example when the feed is lost).
  bool flush(std::string& error);
  // Writes the pending chunk, the index and the trailer, and closes. A file
  // that was never closed is still readable (the reader rebuilds the index).
  bool close(std::string& error);
  // Closes without writing anything more (after a failed write, when the
  // disk is full): the file keeps the whole records written so far, which
  // the reader recovers without an index.
  void abandon();
  bool is_open() const { return fd_ >= 0; }
  std::uint64_t bytes_written() const { return offset_; }

 private:
  bool write_all(std::string_view bytes, std::string& error);
  bool add_encoded(std::string_view frame, std::string& error);
  bool flush_if_full(std::string& error);
  int fd_ = -1;
  std::unique_ptr<proto::FrameDecoder> decoder_;  // transcoding only
  std::unique_ptr<proto::FrameEncoder> encoder_;
  std::unique_ptr<proto::FrameStreamEncoder> stream_;  // the chunk's frames, one range-coded stream
  std::uint64_t skipped_ = 0;
  WriterOptions options_;
  std::uint64_t offset_ = 0;
  proto::rec::ChunkBuilder chunk_;
  std::vector<proto::rec::ChunkInfo> index_;
  std::string path_;
};

}  // namespace mc::record
