#include "server/record/recording_reader.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace mc::record {

namespace rec = proto::rec;

namespace {
const std::shared_ptr<const RecordingHello>& no_hello() {
  static const auto empty = std::make_shared<const RecordingHello>();
  return empty;
}
}  // namespace

RecordingReader::RecordingReader() : hello_(no_hello()) {}

RecordingReader::~RecordingReader() {
  if (fd_ >= 0) ::close(fd_);
}

bool RecordingReader::read_at(std::uint64_t offset, std::size_t size, std::string& out, std::string& error) const {
  // Record lengths come from the file and may claim up to 64 MiB: a large
  // read is first cut to what the file holds past `offset`, so that a
  // damaged length costs no buffer (zeroed, page by page) of that size.
  if (size > (64u << 10)) {
    struct stat st {};
    if (::fstat(fd_, &st) == 0) {
      const auto end = static_cast<std::uint64_t>(st.st_size);
      size = offset >= end ? 0 : static_cast<std::size_t>(std::min<std::uint64_t>(size, end - offset));
    }
  }
  out.resize(size);
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::pread(fd_, out.data() + done, size - done, static_cast<off_t>(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      error = "cannot read recording " + path_ + ": " + std::strerror(errno);
      return false;
    }
    if (n == 0) break;
    done += static_cast<std::size_t>(n);
  }
  out.resize(done);
  return true;
}

bool RecordingReader::open(const std::string& path, std::string& error,
                           std::shared_ptr<const RecordingHello> known) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  hello_ = no_hello();
  stream_.reset();  // it holds a reference to the decoder
  decoder_.reset();
  opened_ = false;
  chunks_.clear();
  recovered_ = false;
  ignored_tail_ = 0;
  skipped_frames_ = 0;
  decoded_frames_ = 0;
  scan_end_ = 0;
  finished_ = false;
  rewind();
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) {
    error = "cannot open recording " + path + ": " + std::strerror(errno);
    return false;
  }
  path_ = path;
  struct stat st {};
  if (::fstat(fd_, &st) != 0) {
    error = "cannot stat recording " + path + ": " + std::strerror(errno);
    return false;
  }
  const auto file_size = static_cast<std::uint64_t>(st.st_size);

  std::string head;
  if (!read_at(0, rec::kFileHeaderSize + 4, head, error)) return false;
  rec::FileHeader header;
  if (!rec::parse_file_header(head, header, error)) {
    error = path + ": " + error;
    return false;
  }
  major_ = header.major;
  // The hello record follows the file header.
  const std::size_t hello_size = rec::record_size_hint(std::string_view(head).substr(rec::kFileHeaderSize));
  std::string hello_bytes;
  rec::RecordView view;
  if (hello_size == 0 || hello_size > rec::kMaxRecordPayload ||
      !read_at(rec::kFileHeaderSize, hello_size, hello_bytes, error) ||
      rec::parse_record(hello_bytes, view, error) != rec::RecordStatus::Ok || view.type != rec::RecordType::Hello) {
    error = path + ": no valid hello record" + (error.empty() ? "" : " (" + error + ")");
    return false;
  }
  if (known && known->major == major_ && known->stored == view.payload) {
    hello_ = std::move(known);
  } else {
    std::string hello_json;
    if (!rec::parse_hello(view.payload, hello_json, error, major_)) {
      error = path + ": " + error;
      return false;
    }
    if (known && known->json == hello_json) {
      hello_ = std::move(known);
    } else {
      auto parsed = std::make_shared<RecordingHello>();
      parsed->json = std::move(hello_json);
      if (!proto::hello_from_json(parsed->json, parsed->hello, error)) {
        error = path + ": " + error;
        return false;
      }
      parsed->stored.assign(view.payload);
      parsed->major = major_;
      hello_ = std::move(parsed);
    }
  }
  data_start_ = rec::kFileHeaderSize + hello_size;

  if (!load_index(file_size)) {
    recovered_ = true;
    chunks_.clear();
    if (!scan(data_start_, file_size, error)) return false;
  }
  opened_ = true;
  return true;
}

// Made when the first frame is read: a reader opened for its hello, its
// index or a spectator who leaves at once never builds the decoder's model.
proto::FrameDecoder& RecordingReader::decoder() {
  if (!decoder_) decoder_ = std::make_unique<proto::FrameDecoder>(hello_->hello.skeleton);
  return *decoder_;
}

bool RecordingReader::load_index(std::uint64_t file_size) {
  if (file_size < data_start_ + rec::kTrailerSize) return false;
  std::string tail, err;
  std::uint64_t index_offset = 0;
  if (!read_at(file_size - rec::kTrailerSize, rec::kTrailerSize, tail, err) || !rec::parse_trailer(tail, index_offset))
    return false;
  if (index_offset < data_start_ || index_offset > file_size - rec::kTrailerSize) return false;
  std::string bytes;
  if (!read_at(index_offset, static_cast<std::size_t>(file_size - rec::kTrailerSize - index_offset), bytes, err))
    return false;
  rec::RecordView view;
  std::vector<rec::ChunkInfo> chunks;
  if (rec::parse_record(bytes, view, err) != rec::RecordStatus::Ok || view.type != rec::RecordType::Index ||
      view.total_size != bytes.size() || !rec::parse_index(view.payload, chunks, err, major_))
    return false;
  for (const auto& c : chunks)
    if (c.offset < data_start_ || c.offset >= index_offset) return false;
  chunks_ = std::move(chunks);
  return true;
}

bool RecordingReader::scan(std::uint64_t from, std::uint64_t file_size, std::string& error) {
  // Records are read a block at a time: a chunk record is a few KB (a
  // second of frames), so one read brings many, where a read for each
  // length and each record was most of opening a file that has no index.
  constexpr std::size_t kBlock = 64u << 10;
  std::uint64_t at = from;
  std::string block, err;
  std::uint64_t block_at = from;  // `block` holds the file's bytes from block_at on
  std::vector<rec::ChunkEntry> entries;
  while (at < file_size) {
    std::string_view rest = std::string_view(block).substr(std::min<std::size_t>(at - block_at, block.size()));
    std::size_t size = rec::record_size_hint(rest);
    if (size > rec::kMaxRecordPayload + rec::kRecordOverhead) break;  // a damaged length: the end
    if (size == 0 || size > rest.size()) {  // the block ends inside this record: read on from it
      // No further than the size known: what is past it is for a later refresh.
      const auto want = static_cast<std::size_t>(std::min<std::uint64_t>(std::max(kBlock, size), file_size - at));
      if (!read_at(at, want, block, error)) return false;
      block_at = at;
      rest = block;
      size = rec::record_size_hint(rest);
    }
    rec::RecordView view;
    if (size == 0 || size > rec::kMaxRecordPayload + rec::kRecordOverhead || size > rest.size() ||
        rec::parse_record(rest.substr(0, size), view, err) != rec::RecordStatus::Ok)
      break;  // the unfinished (or damaged) end: keep what came before
    if (view.type == rec::RecordType::Index) {  // the writer closed the file: no more data
      finished_ = true;
      break;
    }
    if (view.type == rec::RecordType::Chunk) {
      rec::ChunkInfo info;
      if (!rec::parse_chunk(view.payload, info, entries, err, major_)) break;
      info.offset = at;
      chunks_.push_back(info);
    }
    at += size;
  }
  ignored_tail_ = file_size - at;
  scan_end_ = at;
  return true;
}

bool RecordingReader::refresh(std::string& error) {
  if (fd_ < 0 || !recovered_ || finished_) return true;  // an indexed file never grows
  struct stat st {};
  if (::fstat(fd_, &st) != 0) {
    error = "cannot stat recording " + path_ + ": " + std::strerror(errno);
    return false;
  }
  const auto file_size = static_cast<std::uint64_t>(st.st_size);
  if (file_size <= scan_end_) return true;
  // Only whole records past the last one known are taken: a chunk being
  // written right now is picked up by a later refresh.
  return scan(scan_end_, file_size, error);
}

std::uint64_t RecordingReader::frame_count() const {
  std::uint64_t n = 0;
  for (const auto& c : chunks_) n += c.frame_count;
  return n;
}

bool RecordingReader::load_chunk(std::size_t index, std::string& error) {
  const rec::ChunkInfo& c = chunks_[index];
  // One read of a chunk's usual size and some, then a second only for a
  // longer chunk: not one read for its length and another for the rest.
  constexpr std::size_t kReadAhead = 16u << 10;
  if (!read_at(c.offset, kReadAhead, chunk_bytes_, error)) return false;
  const std::size_t size = rec::record_size_hint(chunk_bytes_);
  rec::RecordView view;
  if (size == 0 || size > rec::kMaxRecordPayload + rec::kRecordOverhead ||
      (size > chunk_bytes_.size() && chunk_bytes_.size() == kReadAhead && !read_at(c.offset, size, chunk_bytes_, error)) ||
      rec::parse_record(std::string_view(chunk_bytes_).substr(0, size), view, error) != rec::RecordStatus::Ok ||
      view.type != rec::RecordType::Chunk) {
    error = path_ + ": damaged chunk at offset " + std::to_string(c.offset) + (error.empty() ? "" : ": " + error);
    return false;
  }
  rec::ChunkInfo info;
  std::string_view frame_stream;
  stream_.reset();
  if (!rec::parse_chunk(view.payload, info, entries_, error, major_, &frame_stream)) {
    error = path_ + ": " + error;
    return false;
  }
  if (!frame_stream.empty()) {
    std::uint32_t frames = 0;
    for (const auto& e : entries_) frames += e.kind == rec::ChunkEntry::Kind::StreamFrame ? 1u : 0u;
    stream_.emplace(decoder(), frame_stream,
                    proto::StreamStart{info.first_seq, info.first_time, info.first_stoppage, info.first_substep}, frames);
  }
  chunk_ = index;
  chunk_loaded_ = true;
  entry_ = 0;
  return true;
}

void RecordingReader::rewind() {
  chunk_ = 0;
  chunk_loaded_ = false;
  entry_ = 0;
  at_.reset();
}

bool RecordingReader::next(PoseFrame& out, std::string& error, std::vector<std::string>* controls) {
  error.clear();
  if (!opened_) {
    error = "recording is not open";
    return false;
  }
  at_.reset();
  const auto got = [&] {
    ++decoded_frames_;
    at_.emplace(out.time, out.stoppage);
    return true;
  };
  for (;;) {
    if (!chunk_loaded_ || entry_ >= entries_.size()) {
      const std::size_t next_chunk = chunk_loaded_ ? chunk_ + 1 : chunk_;
      if (next_chunk >= chunks_.size()) return false;  // the end
      if (!load_chunk(next_chunk, error)) return false;
      continue;
    }
    const rec::ChunkEntry& e = entries_[entry_++];
    if (e.kind == rec::ChunkEntry::Kind::Control) {
      if (controls) controls->emplace_back(e.bytes);
      continue;
    }
    if (e.kind == rec::ChunkEntry::Kind::StreamFrame) {
      if (stream_ && stream_->next(out, error)) return got();
      // The rest of this chunk's stream cannot be found: skip it, and wait
      // for a keyframe, as a live client would.
      stream_.reset();
      decoder().reset();
      ++skipped_frames_;
      error.clear();
      continue;
    }
    if (decoder().decode(e.bytes, out, error)) return got();
    // A frame that does not decode (a delta whose base was in a damaged
    // chunk): skip to the next keyframe, as a live client would.
    ++skipped_frames_;
    error.clear();
  }
}

bool RecordingReader::seek(int time, PoseFrame& out, std::string& error, int stoppage) {
  if (chunks_.empty()) {
    error = path_ + ": the recording holds no frames";
    return false;
  }
  const std::size_t key = rec::find_chunk(chunks_, time, stoppage);
  const bool ahead = at_ && chunk_loaded_ && key <= chunk_ &&
                     (at_->first < time || (at_->first == time && at_->second < stoppage));
  if (!ahead) {
    at_.reset();
    decoder().reset();
    if (!load_chunk(key, error)) return false;
  }
  while (next(out, error)) {
    if (out.time > time || (out.time == time && out.stoppage >= stoppage)) return true;
  }
  if (error.empty())
    error = "time " + std::to_string(time) + " is after the end of the recording";
  return false;
}

}  // namespace mc::record
