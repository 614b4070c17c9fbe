// SPEC.md appendix A, the preset DEFLATE dictionary of recordings, read out
// of SPEC.md itself and used as a stranger with only the SPEC would use it:
// the stated length and SHA-256 hold, it is the dictionary the code uses,
// and plain zlib with it inflates the hello and every control block of the
// golden format-3 recording, whose records, chunks and index are walked
// here by the SPEC's section 6 alone (no proto/recording.hpp parsing on
// that side; the code's reader is only the reference it is compared with).
#include <gtest/gtest.h>

#include <openssl/evp.h>
#include <zlib.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "proto/control_binary.hpp"
#include "proto/hello.hpp"
#include "proto/recording.hpp"
#include "proto/text_deflate.hpp"

namespace {

const std::string kSpec = std::string(MATCHCAST_SOURCE_DIR) + "/proto/SPEC.md";
const std::string kGolden = std::string(MATCHCAST_SOURCE_DIR) + "/tests/proto/golden/recording_v3.mcrec";
// How the SPEC marks the appendix and its block.
constexpr std::string_view kAppendixHeading = "## Appendix A. The preset DEFLATE dictionary";
constexpr std::string_view kBlockStart = "```base64 control-dictionary";

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Strict base64 (RFC 4648, with padding); whitespace between lines skipped.
bool base64_decode(std::string_view text, std::string& out) {
  static constexpr std::string_view kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string clean;
  for (char c : text)
    if (c != '\n' && c != '\r' && c != ' ') clean += c;
  if (clean.size() % 4 != 0) return false;
  out.clear();
  for (std::size_t i = 0; i < clean.size(); i += 4) {
    std::uint32_t v = 0;
    int pad = 0;
    for (std::size_t k = 0; k < 4; ++k) {
      const char c = clean[i + k];
      if (c == '=') {
        if (i + 4 != clean.size() || k < 2) return false;
        ++pad;
        v <<= 6;
        continue;
      }
      if (pad > 0) return false;
      const auto at = kAlphabet.find(c);
      if (at == std::string_view::npos) return false;
      v = (v << 6) | static_cast<std::uint32_t>(at);
    }
    out += static_cast<char>(v >> 16);
    if (pad < 2) out += static_cast<char>((v >> 8) & 0xff);
    if (pad < 1) out += static_cast<char>(v & 0xff);
  }
  return true;
}

std::string sha256_hex(std::string_view bytes) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int size = 0;
  EVP_Digest(bytes.data(), bytes.size(), digest, &size, EVP_sha256(), nullptr);
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < size; ++i) out += {kHex[digest[i] >> 4], kHex[digest[i] & 15]};
  return out;
}

// What appendix A says: the dictionary's bytes, and the length and hash it states.
struct Appendix {
  std::string bytes;
  std::string stated_length;  // "885"
  std::string stated_sha256;  // lowercase hex
};

// The text after `key` up to the end of its line, within `in`.
std::string value_after(std::string_view in, std::string_view key) {
  const auto at = in.find(key);
  if (at == std::string_view::npos) return "";
  const auto from = at + key.size();
  return std::string(in.substr(from, in.find('\n', from) - from));
}

::testing::AssertionResult read_appendix(const std::string& spec, Appendix& out) {
  const auto heading = spec.find(kAppendixHeading);
  if (heading == std::string::npos) return ::testing::AssertionFailure() << "SPEC.md has no \"" << kAppendixHeading << "\"";
  const auto block = spec.find(kBlockStart, heading);
  if (block == std::string::npos) return ::testing::AssertionFailure() << "appendix A has no " << kBlockStart << " block";
  const auto body = spec.find('\n', block) + 1;
  const auto end = spec.find("\n```", body);
  if (end == std::string::npos) return ::testing::AssertionFailure() << "appendix A's block is not closed";
  if (!base64_decode(std::string_view(spec).substr(body, end - body), out.bytes))
    return ::testing::AssertionFailure() << "appendix A's block is not base64";
  const std::string_view appendix = std::string_view(spec).substr(heading, end - heading);
  out.stated_length = value_after(appendix, "Length: ");
  out.stated_length = out.stated_length.substr(0, out.stated_length.find(' '));
  out.stated_sha256 = value_after(appendix, "SHA-256: ");
  out.stated_sha256 = out.stated_sha256.substr(0, out.stated_sha256.find_first_of(" .`"));
  return ::testing::AssertionSuccess();
}

// Raw DEFLATE with a preset dictionary, plain zlib, as SPEC section 6 says:
// exactly `size` bytes, the stream's end, no input left over.
bool inflate_with(std::string_view dictionary, std::string_view in, std::size_t size, std::string& out) {
  z_stream z{};
  if (inflateInit2(&z, -15) != Z_OK) return false;
  bool ok = inflateSetDictionary(&z, reinterpret_cast<const Bytef*>(dictionary.data()),
                                 static_cast<uInt>(dictionary.size())) == Z_OK;
  out.assign(size, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  ok = ok && inflate(&z, Z_FINISH) == Z_STREAM_END && z.total_out == size && z.avail_in == 0;
  inflateEnd(&z);
  return ok;
}

// Reads SPEC section 6's numbers off the front of a byte string; any fault sticks.
struct Cursor {
  std::string_view in;
  bool ok = true;
  std::uint64_t le(int bytes) {
    if (in.size() < static_cast<std::size_t>(bytes)) return ok = false, 0;
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= std::uint64_t{static_cast<unsigned char>(in[static_cast<std::size_t>(i)])} << (8 * i);
    in.remove_prefix(static_cast<std::size_t>(bytes));
    return v;
  }
  std::uint32_t leb128() {  // at most 5 bytes, below 2^32
    std::uint64_t v = 0;
    for (int shift = 0; shift < 35; shift += 7) {
      const auto b = le(1);
      v |= (b & 0x7f) << shift;
      if ((b & 0x80) == 0) {
        if (v > 0xffffffffu) ok = false;
        return static_cast<std::uint32_t>(v);
      }
    }
    return ok = false, 0;
  }
  std::int32_t zigzag() {
    const std::uint32_t u = leb128();
    return (u & 1) ? -static_cast<std::int32_t>(u >> 1) - 1 : static_cast<std::int32_t>(u >> 1);
  }
  std::string_view take(std::size_t n) {
    if (in.size() < n) return ok = false, std::string_view();
    const auto out = in.substr(0, n);
    in.remove_prefix(n);
    return out;
  }
};

// SPEC section 6 "chunk info", against `base` (zero in a chunk, the previous entry in the index).
struct ChunkInfo {
  std::uint32_t seq = 0;
  std::int32_t time = 0;
  std::uint32_t stoppage = 0, flags = 0, substep = 0, frames = 0;
};
ChunkInfo read_chunk_info(Cursor& c, const ChunkInfo& base) {
  ChunkInfo i;
  i.seq = base.seq + static_cast<std::uint32_t>(c.zigzag());
  i.time = static_cast<std::int32_t>(static_cast<std::uint32_t>(base.time) + static_cast<std::uint32_t>(c.zigzag()));
  i.stoppage = c.leb128();
  i.flags = static_cast<std::uint32_t>(c.le(1));
  i.substep = static_cast<std::uint32_t>(c.le(1));
  i.frames = c.leb128();
  return i;
}

TEST(SpecDictionary, AppendixHoldsItsStatedLengthAndHash) {
  Appendix a;
  ASSERT_TRUE(read_appendix(read_file(kSpec), a));
  EXPECT_EQ(std::to_string(a.bytes.size()), a.stated_length);
  EXPECT_EQ(sha256_hex(a.bytes), a.stated_sha256);
}

TEST(SpecDictionary, AppendixIsTheDictionaryTheCodeUses) {
  Appendix a;
  ASSERT_TRUE(read_appendix(read_file(kSpec), a));
  EXPECT_EQ(a.bytes, mc::proto::rec::control_dictionary());
}

TEST(SpecDictionary, InflatesTheGoldenRecordingsHelloAndControlBlocksWithPlainZlib) {
  Appendix a;
  ASSERT_TRUE(read_appendix(read_file(kSpec), a));
  const std::string file = read_file(kGolden);
  ASSERT_GT(file.size(), 32u) << kGolden;

  Cursor c{file};
  ASSERT_EQ(c.take(6), std::string_view("MCREC\0", 6));
  ASSERT_EQ(c.le(1), 3u) << "the golden recording of format 3";
  c.le(1);  // minor
  c.le(8);  // created
  std::vector<std::uint64_t> chunk_offsets;
  std::vector<ChunkInfo> chunk_infos;
  int hellos = 0, text_controls = 0, binary_controls = 0, indexes = 0;
  std::uint64_t index_offset = 0;
  while (c.ok && c.in.size() > 16) {
    const std::uint64_t offset = file.size() - c.in.size();  // of the record's length field
    const auto length = static_cast<std::size_t>(c.le(4));
    const std::string_view typed = c.in.substr(0, 1 + length);
    const auto type = c.le(1);
    const std::string_view payload = c.take(length);
    const auto crc = static_cast<std::uint32_t>(c.le(4));
    ASSERT_TRUE(c.ok) << "record at " << offset;
    EXPECT_EQ(crc, ::crc32(0, reinterpret_cast<const Bytef*>(typed.data()), static_cast<uInt>(typed.size())));
    std::string error;
    if (type == 1) {  // hello: u32 text length | raw DEFLATE
      ++hellos;
      Cursor p{payload};
      const auto size = static_cast<std::size_t>(p.le(4));
      std::string text, reference;
      ASSERT_TRUE(inflate_with(a.bytes, p.in, size, text)) << "the hello does not inflate with appendix A";
      ASSERT_TRUE(mc::proto::rec::parse_hello(payload, reference, error)) << error;
      EXPECT_EQ(text, reference);
      mc::proto::Hello hello;
      EXPECT_TRUE(mc::proto::hello_from_json(text, hello, error)) << error;
    } else if (type == 2) {  // chunk
      chunk_offsets.push_back(offset);
      Cursor p{payload};
      chunk_infos.push_back(read_chunk_info(p, ChunkInfo{}));
      const std::uint32_t count = p.leb128();
      std::vector<std::pair<int, std::uint32_t>> controls;  // kind, n
      for (std::uint32_t i = 0; i < count && p.ok; ++i) {
        const auto kind = static_cast<int>(p.le(1));
        const std::uint32_t n = p.leb128();
        ASSERT_GE(kind, 1);
        ASSERT_LE(kind, 5);
        if (kind == 1 || kind == 3) p.take(n);
        if (kind == 2 || kind == 5) controls.emplace_back(kind, n);
      }
      ASSERT_TRUE(p.ok) << "chunk at " << offset;
      if (controls.empty()) continue;
      const std::string_view block = p.take(p.leb128());
      std::size_t total = 0;
      for (const auto& [kind, n] : controls) total += n;
      std::string text;
      ASSERT_TRUE(inflate_with(a.bytes, block, total, text)) << "a control block does not inflate with appendix A";

      // The same messages as the code's reader gives back.
      mc::proto::rec::ChunkInfo info;
      std::vector<mc::proto::rec::ChunkEntry> entries;
      ASSERT_TRUE(mc::proto::rec::parse_chunk(payload, info, entries, error)) << error;
      std::vector<std::string> reference;
      for (const auto& e : entries)
        if (e.kind == mc::proto::rec::ChunkEntry::Kind::Control) reference.push_back(e.bytes);
      ASSERT_EQ(reference.size(), controls.size());
      std::size_t from = 0;
      for (std::size_t i = 0; i < controls.size(); ++i) {
        const std::string_view stored = std::string_view(text).substr(from, controls[i].second);
        from += controls[i].second;
        if (controls[i].first == 2) {
          ++text_controls;
          EXPECT_EQ(stored, reference[i]);
        } else {
          ++binary_controls;
          std::string json;
          ASSERT_TRUE(mc::proto::rec::expand_control(stored, json));
          EXPECT_EQ(json, reference[i]);
        }
      }
    } else if (type == 3) {  // index: u32 count | count x (LEB128 low, high 32 bits of the offset step | chunk info)
      ++indexes;
      index_offset = offset;
      Cursor p{payload};
      const auto count = p.le(4);
      ASSERT_EQ(count, chunk_offsets.size());
      std::uint64_t at = 0;
      ChunkInfo prev;
      for (std::size_t i = 0; i < count; ++i) {
        const std::uint64_t lo = p.leb128(), hi = p.leb128();
        at += (hi << 32) | lo;
        EXPECT_EQ(at, chunk_offsets[i]) << "index entry " << i << ": offsets are from the file's first byte";
        prev = read_chunk_info(p, prev);
        EXPECT_EQ(prev.seq, chunk_infos[i].seq);
        EXPECT_EQ(prev.time, chunk_infos[i].time);
        EXPECT_EQ(prev.frames, chunk_infos[i].frames);
      }
      EXPECT_TRUE(p.ok && p.in.empty());
    } else {
      FAIL() << "unknown record type " << type;
    }
  }
  ASSERT_EQ(c.in.size(), 16u);
  EXPECT_EQ(c.take(8), std::string_view("MCINDEX\0", 8));
  EXPECT_EQ(c.le(8), index_offset);
  EXPECT_EQ(hellos, 1);
  EXPECT_EQ(indexes, 1);
  EXPECT_GE(text_controls, 1) << "the golden recording has a goal event in text form";
  EXPECT_GE(binary_controls, 1) << "and a kick in binary form";
}

}  // namespace
