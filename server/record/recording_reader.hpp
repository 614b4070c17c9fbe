// Reads a recording file (proto/recording.hpp): the hello, then frames in
// order or from any simulation time.
//
// A file without its index (the writer was killed) is recovered by walking
// its records from the start and stopping at the first incomplete or
// corrupt one; everything before it is used. Reads use pread() on demand,
// so a seek touches the index (in memory) and one or two chunks only.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "proto/frame_codec.hpp"
#include "proto/frame_stream.hpp"
#include "proto/hello.hpp"
#include "proto/recording.hpp"

namespace mc::record {

// A recording's hello as open() found it: the JSON text of its hello record
// and what that text says. Immutable, so readers of one file (the relay
// opens one for every spectator's replay) can share it: the hello is a few
// KB of JSON and parsing it was nearly all of open()'s time.
struct RecordingHello {
  std::string json;
  proto::Hello hello;
  // The hello record's payload as the file stores it (deflated from format
  // 3 on): a reader given this hello compares these bytes first and skips
  // the inflate when they match, the common case of one file opened again.
  std::string stored;
  std::uint8_t major = 0;  // the file format `stored` was read from
};

class RecordingReader {
 public:
  RecordingReader();
  ~RecordingReader();
  RecordingReader(const RecordingReader&) = delete;
  RecordingReader& operator=(const RecordingReader&) = delete;

  // False + error when the file cannot be read, is not a recording, has an
  // unknown major version, or lacks a valid hello. A missing or damaged
  // index is not an error: see recovered().
  // `known`: a hello parsed before (shared_hello() of another reader of the
  // same file). When the file's hello text is byte for byte known->json it
  // is taken as it is instead of being parsed again; any other text (a
  // different or changed file) is parsed as usual.
  bool open(const std::string& path, std::string& error, std::shared_ptr<const RecordingHello> known = nullptr);

  const proto::Hello& hello() const { return hello_->hello; }
  const std::string& hello_json() const { return hello_->json; }
  // The hello of the open file, to give to open() of another reader.
  const std::shared_ptr<const RecordingHello>& shared_hello() const { return hello_; }
  const std::vector<proto::rec::ChunkInfo>& chunks() const { return chunks_; }
  std::uint64_t frame_count() const;
  // True when the index was rebuilt by scanning (the file was not closed).
  bool recovered() const { return recovered_; }
  // Bytes at the end of the file that were ignored (an unfinished record).
  std::uint64_t ignored_tail_bytes() const { return ignored_tail_; }
  // Frames next() skipped because they did not decode (waiting for a keyframe).
  std::uint64_t skipped_frames() const { return skipped_frames_; }
  // Frames decoded since open(), by next() and seek() (a seek's cost).
  std::uint64_t decoded_frames() const { return decoded_frames_; }

  // Positions at the first frame at or after simulation time `time`
  // (`stoppage` for the shows repeated during stoppages) and decodes it
  // into `out`. False + error when the time is after the last frame or the
  // data is damaged. next() continues from there. A seek forward with no
  // keyframe chunk between the cursor and the time goes on decoding from
  // the cursor (a replay's skip ahead, a spectator's scrub to the right);
  // any other decodes from the keyframe before the time.
  bool seek(int time, PoseFrame& out, std::string& error, int stoppage = 0);
  // The next frame in stream order, and the control messages (JSON text)
  // recorded between the previous frame and this one. False at the end
  // (error empty) or on damaged data (error set).
  bool next(PoseFrame& out, std::string& error, std::vector<std::string>* controls = nullptr);
  // Back to the first frame.
  void rewind();
  // A recording still being written (no index yet: a live channel's) grows
  // while it is read. This takes in the chunks appended since open() or the
  // last refresh; next() then goes on into them. Cheap when nothing changed
  // (one fstat). False + error only when the file cannot be read.
  bool refresh(std::string& error);
  // Simulation time of the first frame of the last chunk known (0 if none):
  // the latest point a seek can reach.
  int last_chunk_time() const {
    // The last chunk with frames: one of control messages only has no time.
    for (auto it = chunks_.rbegin(); it != chunks_.rend(); ++it)
      if (it->frame_count > 0) return it->first_time;
    return 0;
  }

 private:
  bool read_at(std::uint64_t offset, std::size_t size, std::string& out, std::string& error) const;
  bool load_index(std::uint64_t file_size);
  bool scan(std::uint64_t from, std::uint64_t file_size, std::string& error);
  bool load_chunk(std::size_t index, std::string& error);
  proto::FrameDecoder& decoder();

  int fd_ = -1;
  std::string path_;
  std::shared_ptr<const RecordingHello> hello_;  // never null: an empty one before open()
  // See decoder(). On the heap, made when needed: its model is tens of KB.
  std::unique_ptr<proto::FrameDecoder> decoder_;
  bool opened_ = false;                         // the last open() succeeded
  std::vector<proto::rec::ChunkInfo> chunks_;
  bool recovered_ = false;
  std::uint64_t ignored_tail_ = 0;
  std::uint64_t skipped_frames_ = 0;
  std::uint64_t decoded_frames_ = 0;
  std::uint8_t major_ = proto::rec::kFormatMajor;  // the file's format
  std::uint64_t data_start_ = 0;  // offset of the first chunk record
  std::uint64_t scan_end_ = 0;    // recovered files: where the last scan stopped
  bool finished_ = false;         // recovered files: the scan met the index

  // Cursor: the loaded chunk and the next entry in it.
  std::size_t chunk_ = 0;
  bool chunk_loaded_ = false;
  std::string chunk_bytes_;
  std::vector<proto::rec::ChunkEntry> entries_;
  std::size_t entry_ = 0;
  // Format 3: the loaded chunk's frame stream (a view into chunk_bytes_);
  // empty after a frame of it failed, since the rest cannot be found then.
  std::optional<proto::FrameStreamDecoder> stream_;
  // (time, stoppage) of the frame next() returned last, while the cursor
  // goes on from it: where a seek forward can go on from.
  std::optional<std::pair<int, int>> at_;
};

}  // namespace mc::record
