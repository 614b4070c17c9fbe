#include "server/record/recording_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

#include "proto/hello.hpp"

namespace mc::record {

RecordingWriter::~RecordingWriter() {
  std::string ignored;
  close(ignored);
}

bool RecordingWriter::open(const std::string& path, std::string_view hello_json, std::string& error,
                           WriterOptions options) {
  if (fd_ >= 0) {
    error = "recording already open: " + path_;
    return false;
  }
  options_ = options;
  if (options_.max_chunk_frames < 1) options_.max_chunk_frames = 1;
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    error = "cannot create recording " + path + ": " + std::strerror(errno);
    return false;
  }
  path_ = path;
  offset_ = 0;
  skipped_ = 0;
  index_.clear();
  stream_.reset();
  decoder_.reset();
  encoder_.reset();
  if (options_.keyframe_interval > 0) {
    proto::Hello hello;
    if (!proto::hello_from_json(hello_json, hello, error)) {
      ::close(fd_);
      fd_ = -1;
      error = "cannot record: " + error;
      return false;
    }
    decoder_ = std::make_unique<proto::FrameDecoder>(hello.skeleton);
    encoder_ = std::make_unique<proto::FrameEncoder>(hello.skeleton, proto::EncoderOptions{options_.keyframe_interval});
    stream_ = std::make_unique<proto::FrameStreamEncoder>(*encoder_);
  }
  proto::rec::FileHeader header;
  header.created_unix_ms = options_.created_unix_ms != 0
                               ? options_.created_unix_ms
                               : static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::milliseconds>(
                                                                std::chrono::system_clock::now().time_since_epoch())
                                                                .count());
  return write_all(proto::rec::encode_file_header(header) +
                       proto::rec::encode_record(proto::rec::RecordType::Hello, proto::rec::encode_hello(hello_json)),
                   error);
}

bool RecordingWriter::write_all(std::string_view bytes, std::string& error) {
  // One write() per record in the normal case: a kill between two writes
  // leaves whole records only.
  const std::uint64_t start = offset_;
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      error = "cannot write recording " + path_ + ": " + std::strerror(errno);
      // Cut off the part of the record that did go out: the file then ends
      // with a whole record, as if this write had never started.
      if (offset_ != start && ::ftruncate(fd_, static_cast<off_t>(start)) == 0) offset_ = start;
      return false;
    }
    offset_ += static_cast<std::uint64_t>(n);
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

bool RecordingWriter::flush(std::string& error) {
  if (fd_ < 0) {
    error = "recording is not open";
    return false;
  }
  if (chunk_.empty()) return true;
  proto::rec::ChunkInfo info;
  const std::string record = chunk_.finish(info, stream_ ? stream_->finish() : std::string());
  info.offset = offset_;
  if (!write_all(record, error)) return false;
  index_.push_back(info);
  if (options_.sync && ::fdatasync(fd_) != 0) {
    error = "cannot sync recording " + path_ + ": " + std::strerror(errno);
    return false;
  }
  return true;
}

bool RecordingWriter::add_frame(std::string_view frame, std::string& error) {
  if (fd_ < 0) {
    error = "recording is not open";
    return false;
  }
  if (!decoder_) return add_encoded(frame, error);
  PoseFrame pose;
  std::string why;
  // The frame stream codes substep as one bit (anim makes 0 and 1 only): a
  // frame with another value is skipped like one that does not decode.
  if (!decoder_->decode(frame, pose, why) || pose.substep > 1) {
    ++skipped_;  // the encoder will start the next frame it gets with a keyframe (seq gap)
    return true;
  }
  // A chunk starts at a keyframe whenever possible (see add_encoded).
  if (!chunk_.empty() && (encoder_->next_is_keyframe(pose) || chunk_.frame_count() >= options_.max_chunk_frames) &&
      !flush(error))
    return false;
  chunk_.add_stream_frame(stream_->add(pose));
  return flush_if_full(error);
}

bool RecordingWriter::flush_if_full(std::string& error) {
  // A full chunk goes out now, not when the next frame comes: a kill then
  // loses at most max_chunk_frames - 1 frames (19 = 0.95 s by default).
  return chunk_.frame_count() < options_.max_chunk_frames || flush(error);
}

bool RecordingWriter::add_encoded(std::string_view frame, std::string& error) {
  proto::FrameHeader h;
  if (!proto::peek_header(frame, h, error)) return false;
  // A chunk starts at a keyframe whenever possible, so that a reader can
  // seek to it and decode from there.
  if (!chunk_.empty() && (h.keyframe || chunk_.frame_count() >= options_.max_chunk_frames) && !flush(error))
    return false;
  return chunk_.add_frame(frame, error) && flush_if_full(error);
}

bool RecordingWriter::add_control(std::string_view json_text, std::string& error) {
  if (fd_ < 0) {
    error = "recording is not open";
    return false;
  }
  chunk_.add_control(json_text);
  return true;
}

void RecordingWriter::abandon() {
  if (fd_ < 0) return;
  ::close(fd_);
  fd_ = -1;
  chunk_ = proto::rec::ChunkBuilder();
}

bool RecordingWriter::close(std::string& error) {
  if (fd_ < 0) return true;
  bool ok = flush(error);
  if (ok) {
    const std::uint64_t index_offset = offset_;
    ok = write_all(proto::rec::encode_index(index_) + proto::rec::encode_trailer(index_offset), error);
  }
  if (ok && options_.sync && ::fdatasync(fd_) != 0) {
    error = "cannot sync recording " + path_ + ": " + std::strerror(errno);
    ok = false;
  }
  ::close(fd_);
  fd_ = -1;
  return ok;
}

}  // namespace mc::record
