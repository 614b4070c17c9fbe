// Writes a recording file (proto/recording.hpp) while the stream runs.
//
// Safety: the file is only ever appended to. Frames are collected into a
// chunk in memory and each chunk is written with one write() when the next
// keyframe arrives (or after max_chunk_frames), then fdatasync'ed if
// `sync` is set. A crash or SIGKILL therefore loses at most the chunk being
// collected (one keyframe interval, 1 s by default) and never touches bytes
// already written; the reader drops a half-written last record.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "proto/recording.hpp"

namespace mc::record {

struct WriterOptions {
  // Write a chunk after this many frames even if no keyframe came (a chunk
  // is the most a crash can lose; 20 frames = 1 s at 20 Hz).
  std::uint32_t max_chunk_frames = 20;
  // fdatasync after each chunk, so that a power cut also loses at most one
  // chunk. SIGKILL-safety does not need it (the page cache survives).
  bool sync = true;
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
  // Appends one encoded pose frame, exactly as sent to spectators.
  bool add_frame(std::string_view frame, std::string& error);
  // Appends one JSON control message (event or metadata) in stream order.
  bool add_control(std::string_view json_text, std::string& error);
  // Writes the pending chunk now (for example when the feed is lost).
  bool flush(std::string& error);
  // Writes the pending chunk, the index and the trailer, and closes. A file
  // that was never closed is still readable (the reader rebuilds the index).
  bool close(std::string& error);
  bool is_open() const { return fd_ >= 0; }
  std::uint64_t bytes_written() const { return offset_; }

 private:
  bool write_all(std::string_view bytes, std::string& error);
  int fd_ = -1;
  WriterOptions options_;
  std::uint64_t offset_ = 0;
  proto::rec::ChunkBuilder chunk_;
  std::vector<proto::rec::ChunkInfo> index_;
  std::string path_;
};

}  // namespace mc::record
