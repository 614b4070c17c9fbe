// Plain and gzip byte sources: sniffing by magic, streaming inflate,
// concatenated members, and truncated / corrupt input reported with offsets.
#include "server/ingest/byte_source.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <fstream>

namespace mc::ingest {
namespace {

std::string gzip(const std::string& text) {
  z_stream zs{};
  deflateInit2(&zs, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY);
  std::string out(deflateBound(&zs, text.size()) + 64, '\0');
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
  zs.avail_in = static_cast<uInt>(text.size());
  zs.next_out = reinterpret_cast<Bytef*>(out.data());
  zs.avail_out = static_cast<uInt>(out.size());
  deflate(&zs, Z_FINISH);
  out.resize(zs.total_out);
  deflateEnd(&zs);
  return out;
}

std::string drain(ByteSource& s, std::size_t chunk = 7) {
  std::string out(chunk, '\0'), all;
  while (std::size_t n = s.read(out.data(), chunk)) all.append(out.data(), n);
  return all;
}

TEST(ByteSource, PlainBytesPassThrough) {
  auto s = open_memory_source("ULG5\n(show 1)\n");
  EXPECT_EQ(drain(*s), "ULG5\n(show 1)\n");
  EXPECT_EQ(s->error(), "");
}

TEST(ByteSource, GzipIsSniffedAndInflated) {
  std::string text;
  for (int i = 0; i < 10000; ++i) text += "(show " + std::to_string(i) + ")\n";
  const std::string gz = gzip(text);
  auto s = open_memory_source(gz);
  EXPECT_EQ(drain(*s, 4096), text);
  EXPECT_EQ(s->error(), "");
  EXPECT_EQ(s->raw_offset(), gz.size());
}

TEST(ByteSource, ConcatenatedMembersAreReadInTurn) {
  const std::string both = gzip("first\n") + gzip("second\n");
  auto s = open_memory_source(both);
  EXPECT_EQ(drain(*s), "first\nsecond\n");
  EXPECT_EQ(s->error(), "");
}

TEST(ByteSource, TruncatedGzipKeepsWhatWasDecodedAndSaysWhere) {
  std::string text;
  for (int i = 0; i < 20000; ++i) text += "line " + std::to_string(i) + "\n";
  const std::string gz = gzip(text);
  auto s = open_memory_source(std::string_view(gz).substr(0, gz.size() / 2));
  const std::string got = drain(*s, 1000);
  EXPECT_FALSE(got.empty());
  EXPECT_EQ(text.compare(0, got.size(), got), 0);  // a prefix of the original
  EXPECT_NE(s->error().find("truncated gzip"), std::string::npos) << s->error();
  EXPECT_NE(s->error().find(std::to_string(gz.size() / 2)), std::string::npos) << s->error();
}

TEST(ByteSource, CorruptGzipIsAnErrorNotACrash) {
  std::string gz = gzip(std::string(5000, 'x') + "tail");
  for (std::size_t i = 12; i < gz.size(); i += 3) gz[i] = static_cast<char>(gz[i] ^ 0x5a);
  auto s = open_memory_source(gz);
  drain(*s);
  EXPECT_NE(s->error(), "");
}

TEST(ByteSource, FilesOpenAndMissingFilesFail) {
  const std::string path = ::testing::TempDir() + "/byte_source_test.gz";
  std::ofstream(path, std::ios::binary) << gzip("hello\n");
  std::string err;
  auto s = open_file_source(path, err);
  ASSERT_TRUE(s) << err;
  EXPECT_EQ(drain(*s), "hello\n");
  EXPECT_FALSE(open_file_source(path + ".missing", err));
  EXPECT_NE(err.find("cannot open"), std::string::npos);
}

TEST(ByteSource, EmptyAndOneByteInputs) {
  auto e = open_memory_source("");
  EXPECT_EQ(drain(*e), "");
  auto one = open_memory_source("\x1f");
  EXPECT_EQ(drain(*one), "\x1f");
  auto magic_only = open_memory_source("\x1f\x8b");
  EXPECT_EQ(drain(*magic_only), "");
  EXPECT_NE(magic_only->error(), "");
}

}  // namespace
}  // namespace mc::ingest
