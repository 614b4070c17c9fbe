#include "proto/recording.hpp"

#include <zlib.h>

#include <algorithm>
#include <utility>

#include "proto/control_binary.hpp"
#include "proto/text_deflate.hpp"

namespace mc::proto::rec {
namespace {

constexpr char kMagic[6] = {'M', 'C', 'R', 'E', 'C', '\0'};
constexpr char kTrailerMagic[8] = {'M', 'C', 'I', 'N', 'D', 'E', 'X', '\0'};
constexpr std::size_t kChunkHeaderSize = 20;
constexpr std::size_t kIndexEntrySize = 24;

void put(std::string& out, std::uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
}
std::uint64_t get(std::string_view in, std::size_t at, int bytes) {
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v |= static_cast<std::uint64_t>(static_cast<unsigned char>(in[at + static_cast<std::size_t>(i)])) << (8 * i);
  return v;
}
void put_varint(std::string& out, std::uint32_t v) {
  while (v >= 0x80) {
    out.push_back(static_cast<char>((v & 0x7f) | 0x80));
    v >>= 7;
  }
  out.push_back(static_cast<char>(v));
}
// False when the varint runs past `in` or exceeds 32 bits.
bool get_varint(std::string_view in, std::size_t& at, std::uint32_t& v) {
  v = 0;
  for (int shift = 0; shift < 35; shift += 7) {
    if (at >= in.size()) return false;
    const auto b = static_cast<unsigned char>(in[at++]);
    v |= static_cast<std::uint32_t>(b & 0x7f) << shift;
    if ((b & 0x80) == 0) return shift < 28 || (b >> 4) == 0;
  }
  return false;
}

// Formats 1 and 2 (read only): the chunk info in 16 fixed bytes, u32 first
// seq | i32 first time | u16 first stoppage | u8 first substep | u8 flags |
// u32 frame count.
void get_chunk_info(std::string_view in, std::size_t at, ChunkInfo& c) {
  c.first_seq = static_cast<std::uint32_t>(get(in, at, 4));
  c.first_time = static_cast<int>(static_cast<std::int32_t>(get(in, at + 4, 4)));
  c.first_stoppage = static_cast<int>(get(in, at + 8, 2));
  c.first_substep = static_cast<std::uint8_t>(get(in, at + 10, 1));
  c.starts_with_keyframe = (get(in, at + 11, 1) & 1u) != 0;
  c.frame_count = static_cast<std::uint32_t>(get(in, at + 12, 4));
}

std::uint32_t zigzag(std::int32_t v) {
  return v >= 0 ? static_cast<std::uint32_t>(v) << 1 : (static_cast<std::uint32_t>(-(v + 1)) << 1) | 1u;
}
std::int32_t unzigzag(std::uint32_t u) {
  return (u & 1u) ? -static_cast<std::int32_t>(u >> 1) - 1 : static_cast<std::int32_t>(u >> 1);
}

// Format 3: the chunk info in LEB128 numbers, each against `base` (the
// previous chunk's info in the index; zero in a chunk's own header):
// seq change (zigzag, mod 2^32) | time change (zigzag) | stoppage | u8 flags
// (bit 0 keyframe) | u8 substep | frame count. ~8 bytes instead of 16.
void put_chunk_info_v3(std::string& out, const ChunkInfo& c, const ChunkInfo& base) {
  put_varint(out, zigzag(static_cast<std::int32_t>(c.first_seq - base.first_seq)));
  put_varint(out, zigzag(static_cast<std::int32_t>(static_cast<std::uint32_t>(c.first_time) - static_cast<std::uint32_t>(base.first_time))));
  put_varint(out, static_cast<std::uint32_t>(c.first_stoppage));
  out.push_back(static_cast<char>(c.starts_with_keyframe ? 1 : 0));
  out.push_back(static_cast<char>(c.first_substep));
  put_varint(out, c.frame_count);
}
bool get_chunk_info_v3(std::string_view in, std::size_t& at, ChunkInfo& c, const ChunkInfo& base) {
  std::uint32_t seq = 0, time = 0, stoppage = 0;
  if (!get_varint(in, at, seq) || !get_varint(in, at, time) || !get_varint(in, at, stoppage) || stoppage > 65535 ||
      in.size() - at < 2)
    return false;
  const auto flags = static_cast<unsigned char>(in[at]);
  c.first_substep = static_cast<std::uint8_t>(in[at + 1]);
  at += 2;
  if (flags > 1 || !get_varint(in, at, c.frame_count)) return false;
  c.first_seq = base.first_seq + static_cast<std::uint32_t>(unzigzag(seq));
  c.first_time = static_cast<int>(static_cast<std::int32_t>(static_cast<std::uint32_t>(base.first_time) +
                                                            static_cast<std::uint32_t>(unzigzag(time))));
  c.first_stoppage = static_cast<int>(stoppage);
  c.starts_with_keyframe = flags == 1;
  return true;
}

}  // namespace

// zlib's CRC-32 (SPEC.md: the same polynomial, initial value and final
// xor): every record of a recording is checked with it on every read, and
// zlib's sliced tables run several times faster than a byte-at-a-time loop.
std::uint32_t crc32(std::string_view bytes, std::uint32_t crc) {
  while (!bytes.empty()) {  // uInt is 32 bits: a longer view goes in pieces
    const auto n = static_cast<uInt>(std::min<std::size_t>(bytes.size(), 1u << 30));
    crc = static_cast<std::uint32_t>(::crc32(crc, reinterpret_cast<const Bytef*>(bytes.data()), n));
    bytes.remove_prefix(n);
  }
  return crc;
}

std::string encode_file_header(const FileHeader& h) {
  std::string out(kMagic, sizeof kMagic);
  out.push_back(static_cast<char>(h.major));
  out.push_back(static_cast<char>(h.minor));
  put(out, h.created_unix_ms, 8);
  return out;
}

bool parse_file_header(std::string_view bytes, FileHeader& out, std::string& error) {
  if (bytes.size() < kFileHeaderSize) {
    error = "recording truncated: no complete file header";
    return false;
  }
  if (bytes.substr(0, sizeof kMagic) != std::string_view(kMagic, sizeof kMagic)) {
    error = "not a Matchcast recording (bad magic)";
    return false;
  }
  out.major = static_cast<std::uint8_t>(bytes[6]);
  out.minor = static_cast<std::uint8_t>(bytes[7]);
  out.created_unix_ms = get(bytes, 8, 8);
  if (out.major < kOldestMajor || out.major > kFormatMajor) {
    error = "unsupported recording format major version " + std::to_string(out.major) + " (this reader reads " +
            std::to_string(kOldestMajor) + " to " + std::to_string(kFormatMajor) + ")";
    return false;
  }
  return true;
}

std::string encode_record(RecordType type, std::string_view payload) {
  std::string out;
  out.reserve(payload.size() + kRecordOverhead);
  put(out, payload.size(), 4);
  out.push_back(static_cast<char>(type));
  out.append(payload);
  put(out, crc32(std::string_view(out).substr(4)), 4);
  return out;
}

std::size_t record_size_hint(std::string_view bytes) {
  if (bytes.size() < 4) return 0;
  return static_cast<std::size_t>(get(bytes, 0, 4)) + kRecordOverhead;
}

RecordStatus parse_record(std::string_view bytes, RecordView& out, std::string& error) {
  if (bytes.size() < 5) {
    error = "record truncated in its header";
    return RecordStatus::Truncated;
  }
  const auto length = static_cast<std::uint32_t>(get(bytes, 0, 4));
  if (length > kMaxRecordPayload) {
    error = "corrupt record: length " + std::to_string(length);
    return RecordStatus::Corrupt;
  }
  const std::size_t total = length + kRecordOverhead;
  if (bytes.size() < total) {
    error = "record truncated: " + std::to_string(bytes.size()) + " of " + std::to_string(total) + " bytes";
    return RecordStatus::Truncated;
  }
  const auto type = static_cast<unsigned char>(bytes[4]);
  if (type < 1 || type > 3) {
    error = "corrupt record: unknown type " + std::to_string(type);
    return RecordStatus::Corrupt;
  }
  if (crc32(bytes.substr(4, 1 + length)) != static_cast<std::uint32_t>(get(bytes, 5 + length, 4))) {
    error = "corrupt record: CRC mismatch";
    return RecordStatus::Corrupt;
  }
  out.type = static_cast<RecordType>(type);
  out.payload = bytes.substr(5, length);
  out.total_size = total;
  return RecordStatus::Ok;
}

namespace {

// Entry kinds on disk: 1 whole frame, 2 control message, 3 frame whose header
// is coded against the previous frame of the chunk, 4 (format 3) a run of
// frames in the chunk's frame stream (LEB128 count instead of a length), 5
// (format 3) a control message in binary form (control_binary.hpp).
constexpr std::uint8_t kEntryFrame = 1, kEntryControl = 2, kEntryCompactFrame = 3, kEntryStreamRun = 4,
                       kEntryBinaryControl = 5;

// Compact header: u8 flags (bit 0 keyframe, bit 1 substep, bit 2 seq given,
// bit 3 play mode and score given), varint zigzag time change, varint
// stoppage, varint zigzag server-time change, [varint seq], [3 bytes mode,
// score left, score right]. Empty when the header cannot be coded so (major,
// minor or reserved flag bits differ, odd substep value).
std::string compact_header(std::string_view prev, std::string_view cur) {
  FrameHeader p, c;
  std::string err;
  if (!peek_header(prev, p, err) || !peek_header(cur, c, err)) return {};
  if (p.major != c.major || p.minor != c.minor || static_cast<unsigned char>(cur[3]) > 1 || c.substep > 1) return {};
  const bool seq_given = c.seq != p.seq + 1;
  const bool mode_given = c.play_mode != p.play_mode || c.score_left != p.score_left || c.score_right != p.score_right;
  std::string out;
  out.push_back(static_cast<char>((c.keyframe ? 1 : 0) | (c.substep ? 2 : 0) | (seq_given ? 4 : 0) | (mode_given ? 8 : 0)));
  const auto zz = [](std::int64_t v) { return static_cast<std::uint64_t>(v >= 0 ? v * 2 : -v * 2 - 1); };
  const std::uint64_t dt = zz(static_cast<std::int64_t>(c.time) - p.time);
  const std::uint64_t ds = zz(static_cast<std::int64_t>(c.server_time_ms) - static_cast<std::int64_t>(p.server_time_ms));
  if (dt > 0xffffffffu || ds > 0xffffffffu) return {};
  put_varint(out, static_cast<std::uint32_t>(dt));
  put_varint(out, static_cast<std::uint32_t>(c.stoppage));
  put_varint(out, static_cast<std::uint32_t>(ds));
  if (seq_given) put_varint(out, c.seq);
  if (mode_given) {
    out.push_back(static_cast<char>(c.play_mode));
    out.push_back(static_cast<char>(c.score_left));
    out.push_back(static_cast<char>(c.score_right));
  }
  return out;
}

// Restores a 26-byte header from a compact one; false when malformed.
bool expand_header(std::string_view prev, std::string_view in, std::size_t& at, std::string& out) {
  FrameHeader p;
  std::string err;
  if (!peek_header(prev, p, err) || at >= in.size()) return false;
  const auto flags = static_cast<unsigned char>(in[at++]);
  if (flags > 15) return false;
  std::uint32_t dt = 0, stoppage = 0, ds = 0, seq = p.seq + 1;
  if (!get_varint(in, at, dt) || !get_varint(in, at, stoppage) || !get_varint(in, at, ds) || stoppage > 65535) return false;
  if ((flags & 4) && !get_varint(in, at, seq)) return false;
  FrameHeader c = p;
  if (flags & 8) {
    if (in.size() - at < 3) return false;
    c.play_mode = static_cast<std::uint8_t>(in[at]);
    c.score_left = static_cast<std::uint8_t>(in[at + 1]);
    c.score_right = static_cast<std::uint8_t>(in[at + 2]);
    at += 3;
  }
  const auto unzz = [](std::uint32_t u) { return (u & 1) ? -static_cast<std::int64_t>(u >> 1) - 1 : static_cast<std::int64_t>(u >> 1); };
  c.keyframe = (flags & 1) != 0;
  c.substep = (flags & 2) ? 1 : 0;
  c.seq = seq;
  c.time = static_cast<int>(p.time + unzz(dt));
  c.stoppage = static_cast<int>(stoppage);
  c.server_time_ms = static_cast<std::uint64_t>(static_cast<std::int64_t>(p.server_time_ms) + unzz(ds));
  out.clear();
  write_header(c, out);
  return true;
}

}  // namespace

void ChunkBuilder::add(ChunkEntry::Kind kind, std::string_view bytes) {
  body_.push_back(static_cast<char>(kind == ChunkEntry::Kind::Frame ? kEntryFrame : kEntryControl));
  put_varint(body_, static_cast<std::uint32_t>(bytes.size()));
  body_.append(bytes);
  ++entries_;
}

void ChunkBuilder::note_first(const FrameHeader& h) {
  if (info_.frame_count == 0) {
    info_.first_seq = h.seq;
    info_.first_time = h.time;
    info_.first_stoppage = h.stoppage;
    info_.first_substep = h.substep;
    info_.starts_with_keyframe = h.keyframe;
  }
  ++info_.frame_count;
}

bool ChunkBuilder::add_frame(std::string_view frame, std::string& error) {
  FrameHeader h;
  if (!peek_header(frame, h, error)) return false;
  note_first(h);
  const std::string compact = last_header_.empty() ? std::string() : compact_header(last_header_, frame);
  last_header_.assign(frame.substr(0, kFrameHeaderSize));
  if (compact.empty()) {
    add(ChunkEntry::Kind::Frame, frame);
  } else {
    body_.push_back(static_cast<char>(kEntryCompactFrame));
    put_varint(body_, static_cast<std::uint32_t>(compact.size() + frame.size() - kFrameHeaderSize));
    body_ += compact;
    body_.append(frame.substr(kFrameHeaderSize));
    ++entries_;
  }
  return true;
}

void ChunkBuilder::add_stream_frame(const FrameHeader& header) {
  note_first(header);
  ++stream_run_;
}

void ChunkBuilder::end_stream_run() {
  if (stream_run_ == 0) return;
  body_.push_back(static_cast<char>(kEntryStreamRun));
  put_varint(body_, stream_run_);
  ++entries_;
  stream_run_ = 0;
}

void ChunkBuilder::add_control(std::string_view json_text) {
  // Format 2: the entry keeps its place and length; the text goes to the
  // chunk's deflated block.
  // Format 3: a stamina update or a kick in binary form, in the same block.
  end_stream_run();
  const std::string binary = compact_control(json_text);
  const std::string_view stored = binary.empty() ? json_text : std::string_view(binary);
  body_.push_back(static_cast<char>(binary.empty() ? kEntryControl : kEntryBinaryControl));
  put_varint(body_, static_cast<std::uint32_t>(stored.size()));
  controls_.append(stored);
  ++entries_;
}

std::string ChunkBuilder::finish(ChunkInfo& info, std::string_view frame_stream) {
  end_stream_run();
  std::string payload;
  payload.reserve(kChunkHeaderSize + body_.size() + frame_stream.size() + 16);
  put_chunk_info_v3(payload, info_, ChunkInfo{});
  put_varint(payload, entries_);
  payload += body_;
  if (!controls_.empty()) {
    // Format 3: the block's length, since the frame stream follows it.
    const std::string block = deflate_text(controls_);
    put_varint(payload, static_cast<std::uint32_t>(block.size()));
    payload += block;
  }
  payload.append(frame_stream);
  info = info_;
  body_.clear();
  controls_.clear();
  entries_ = 0;
  info_ = ChunkInfo{};
  last_header_.clear();
  return encode_record(RecordType::Chunk, payload);
}

bool parse_chunk(std::string_view payload, ChunkInfo& info, std::vector<ChunkEntry>& entries, std::string& error,
                 std::uint8_t major, std::string_view* frame_stream) {
  entries.clear();
  if (frame_stream) *frame_stream = {};
  std::size_t at = kChunkHeaderSize;
  std::uint32_t count = 0;
  if (major >= 3) {
    at = 0;
    info = ChunkInfo{};
    if (!get_chunk_info_v3(payload, at, info, ChunkInfo{}) || !get_varint(payload, at, count)) {
      error = "corrupt chunk: bad header";
      return false;
    }
  } else {
    if (payload.size() < kChunkHeaderSize) {
      error = "corrupt chunk: shorter than its header";
      return false;
    }
    get_chunk_info(payload, 0, info);
    count = static_cast<std::uint32_t>(get(payload, 16, 4));
  }
  std::uint32_t frames = 0;
  std::string last_header;  // of the previous frame in this chunk
  // Format 2: the control messages' lengths, in entry order; their text
  // follows the entries, deflated as one block.
  const bool deflated = major >= 2;
  std::vector<std::pair<std::size_t, std::uint32_t>> control_entries;  // entry index, length
  std::vector<bool> binary_entries;  // per control entry: stored in binary form (format 3)
  std::size_t control_bytes = 0;
  std::uint32_t stream_frames = 0;
  for (std::uint32_t i = 0; i < count; ++i) {
    const auto bad = [&] {
      error = "corrupt chunk: bad entry " + std::to_string(i);
      return false;
    };
    if (at >= payload.size()) return bad();
    const auto kind = static_cast<unsigned char>(payload[at++]);
    std::uint32_t len = 0;
    const unsigned char last_kind = major >= 3 ? kEntryBinaryControl : kEntryCompactFrame;
    if (kind < kEntryFrame || kind > last_kind || !get_varint(payload, at, len)) return bad();
    if (kind == kEntryStreamRun) {
      // A hostile count allocates nothing: the chunk's own frame count
      // (itself bounded) must cover it.
      if (len == 0 || info.frame_count > kMaxChunkFrames || frames > info.frame_count || len > info.frame_count - frames)
        return bad();
      entries.insert(entries.end(), len, ChunkEntry{ChunkEntry::Kind::StreamFrame, std::string()});
      frames += len;
      stream_frames += len;
      continue;
    }
    if ((kind == kEntryControl || kind == kEntryBinaryControl) && deflated) {
      control_bytes += len;
      if (control_bytes > kMaxRecordPayload) return bad();
      control_entries.emplace_back(entries.size(), len);
      binary_entries.push_back(kind == kEntryBinaryControl);
      entries.push_back({ChunkEntry::Kind::Control, std::string()});
      continue;
    }
    if (len > payload.size() - at) return bad();
    const std::string_view entry = payload.substr(at, len);
    at += len;
    if (kind == kEntryControl) {
      entries.push_back({ChunkEntry::Kind::Control, std::string(entry)});
      continue;
    }
    std::string frame;
    if (kind == kEntryFrame) {
      frame.assign(entry);
    } else {
      std::size_t pos = 0;
      if (last_header.empty() || !expand_header(last_header, entry, pos, frame)) return bad();
      frame.append(entry.substr(pos));
    }
    if (frame.size() < kFrameHeaderSize) return bad();
    last_header = frame.substr(0, kFrameHeaderSize);
    entries.push_back({ChunkEntry::Kind::Frame, std::move(frame)});
    ++frames;
  }
  if (frames != info.frame_count) {
    error = "corrupt chunk: entry count does not match its contents";
    return false;
  }
  if (control_bytes > 0) {
    // DEFLATE expands at most ~1032:1: a larger claim is corruption, refused
    // before anything is allocated for it.
    std::string_view block = payload.substr(at);
    if (major >= 3) {
      std::uint32_t size = 0;
      if (!get_varint(payload, at, size) || size > payload.size() - at) {
        error = "corrupt chunk: bad control block length";
        return false;
      }
      block = payload.substr(at, size);
    }
    std::string text;
    if (control_bytes > 1100 * block.size() + 64 || !inflate_text(block, control_bytes, text)) {
      error = "corrupt chunk: its control messages do not inflate";
      return false;
    }
    std::size_t from = 0;
    for (std::size_t i = 0; i < control_entries.size(); ++i) {
      const auto [e, len] = control_entries[i];
      if (!binary_entries[i]) {
        entries[e].bytes.assign(text, from, len);
      } else if (!expand_control(std::string_view(text).substr(from, len), entries[e].bytes)) {
        error = "corrupt chunk: a control message in binary form does not decode";
        return false;
      }
      from += len;
    }
    at += block.size();
    if (major < 3) at = payload.size();
  }
  if (stream_frames > 0) {
    // Format 3: the frame stream, to the end of the payload.
    if (at >= payload.size()) {
      error = "corrupt chunk: its frame stream is missing";
      return false;
    }
    if (frame_stream) *frame_stream = payload.substr(at);
    at = payload.size();
  }
  if (at != payload.size()) {
    error = "corrupt chunk: bytes after its entries";
    return false;
  }
  return true;
}

std::string encode_index(const std::vector<ChunkInfo>& chunks) {
  // Format 3: u32 count, then per chunk the LEB128 change of its offset and
  // its info against the previous chunk's (~9 bytes instead of 24).
  std::string payload;
  payload.reserve(4 + chunks.size() * 10);
  put(payload, chunks.size(), 4);
  ChunkInfo prev;
  for (const auto& c : chunks) {
    const std::uint64_t step = c.offset - prev.offset;
    put_varint(payload, static_cast<std::uint32_t>(step & 0xffffffffu));
    put_varint(payload, static_cast<std::uint32_t>(step >> 32));
    put_chunk_info_v3(payload, c, prev);
    prev = c;
  }
  return encode_record(RecordType::Index, payload);
}

bool parse_index(std::string_view payload, std::vector<ChunkInfo>& out, std::string& error, std::uint8_t major) {
  out.clear();
  const auto bad = [&] {
    out.clear();
    error = "corrupt index: size does not match its count";
    return false;
  };
  if (payload.size() < 4) return bad();
  const std::uint64_t count = get(payload, 0, 4);
  if (major < 3) {
    if ((payload.size() - 4) % kIndexEntrySize != 0 || count != (payload.size() - 4) / kIndexEntrySize) return bad();
    for (std::size_t at = 4; at < payload.size(); at += kIndexEntrySize) {
      ChunkInfo c;
      c.offset = get(payload, at, 8);
      get_chunk_info(payload, at + 8, c);
      out.push_back(c);
    }
    return true;
  }
  // An entry takes at least 7 bytes: a hostile count allocates nothing.
  if (count > (payload.size() - 4) / 7) return bad();
  out.reserve(static_cast<std::size_t>(count));
  std::size_t at = 4;
  ChunkInfo prev;
  for (std::uint64_t i = 0; i < count; ++i) {
    std::uint32_t lo = 0, hi = 0;
    ChunkInfo c;
    if (!get_varint(payload, at, lo) || !get_varint(payload, at, hi) || !get_chunk_info_v3(payload, at, c, prev))
      return bad();
    c.offset = prev.offset + ((static_cast<std::uint64_t>(hi) << 32) | lo);
    out.push_back(c);
    prev = c;
  }
  if (at != payload.size()) return bad();
  return true;
}

std::string encode_hello(std::string_view json_text) {
  // Format 3: u32 text length | the text deflated (text_deflate.hpp).
  std::string payload;
  put(payload, json_text.size(), 4);
  payload += deflate_text(json_text);
  return payload;
}

bool parse_hello(std::string_view payload, std::string& json_text, std::string& error, std::uint8_t major) {
  if (major < 3) {
    json_text.assign(payload);
    return true;
  }
  if (payload.size() < 4) {
    error = "corrupt hello record: shorter than its header";
    return false;
  }
  const std::uint64_t size = get(payload, 0, 4);
  const std::string_view block = payload.substr(4);
  if (size > 1100 * block.size() + 64 || !inflate_text(block, static_cast<std::size_t>(size), json_text)) {
    error = "corrupt hello record: its text does not inflate";
    return false;
  }
  return true;
}

std::string encode_trailer(std::uint64_t index_offset) {
  std::string out(kTrailerMagic, sizeof kTrailerMagic);
  put(out, index_offset, 8);
  return out;
}

bool parse_trailer(std::string_view last16, std::uint64_t& index_offset) {
  if (last16.size() != kTrailerSize || last16.substr(0, 8) != std::string_view(kTrailerMagic, 8)) return false;
  index_offset = get(last16, 8, 8);
  return true;
}

std::size_t find_chunk(const std::vector<ChunkInfo>& chunks, int time, int stoppage) {
  if (chunks.empty()) return 0;
  // Binary search on (first_time, first_stoppage): chunks are in stream
  // order, but a chunk of control messages only has no frame and so no
  // time (all 0, SPEC.md 6): one stands before every keyframe chunk of the
  // server's recordings, and taking its 0 as a time sent a seek to the
  // wrong half. The search looks past them to the next chunk with frames.
  const auto at_or_before = [&](const ChunkInfo& c) {
    return c.first_time < time ||
           (c.first_time == time &&
            (c.first_stoppage < stoppage || (c.first_stoppage == stoppage && c.first_substep == 0)));
  };
  std::size_t lo = 0, hi = chunks.size();  // the answer is in [lo, hi)
  while (hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    std::size_t m = mid;
    while (m < hi && chunks[m].frame_count == 0) ++m;
    if (m < hi && at_or_before(chunks[m]))
      lo = m;
    else
      hi = mid;  // [mid, m) hold no frames, chunk m (if any) is after the time
  }
  while (lo > 0 && !chunks[lo].starts_with_keyframe) --lo;
  return lo;
}

}  // namespace mc::proto::rec
