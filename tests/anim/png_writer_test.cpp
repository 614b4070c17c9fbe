#include "anim/tools/png_writer.hpp"

#include <string>

#include <gtest/gtest.h>
#include <zlib.h>

namespace mc::anim::tools {
namespace {

std::uint32_t be32(const std::string& s, std::size_t at) {
  return (static_cast<std::uint32_t>(static_cast<unsigned char>(s[at])) << 24) |
         (static_cast<std::uint32_t>(static_cast<unsigned char>(s[at + 1])) << 16) |
         (static_cast<std::uint32_t>(static_cast<unsigned char>(s[at + 2])) << 8) |
         static_cast<std::uint32_t>(static_cast<unsigned char>(s[at + 3]));
}

TEST(PngWriter, WritesAValidRgbPng) {
  Image img(3, 2);
  img.set(1, 1, 10, 20, 30);
  const std::string png = encode_png(img);
  ASSERT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(png.substr(12, 4), "IHDR");
  EXPECT_EQ(be32(png, 16), 3u);
  EXPECT_EQ(be32(png, 20), 2u);
  // Every chunk's CRC covers its type and data.
  std::size_t at = 8;
  std::string idat;
  while (at < png.size()) {
    const std::uint32_t len = be32(png, at);
    const std::string body = png.substr(at + 4, 4 + len);
    EXPECT_EQ(be32(png, at + 8 + len),
              static_cast<std::uint32_t>(crc32(0L, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()))));
    if (body.substr(0, 4) == "IDAT") idat += body.substr(4);
    at += 12 + len;
  }
  EXPECT_EQ(at, png.size());
  // The pixels come back: one filter byte then RGB per row.
  std::string raw(2 * (1 + 9), '\0');
  uLongf n = static_cast<uLongf>(raw.size());
  ASSERT_EQ(uncompress(reinterpret_cast<Bytef*>(raw.data()), &n, reinterpret_cast<const Bytef*>(idat.data()),
                       static_cast<uLong>(idat.size())), Z_OK);
  EXPECT_EQ(static_cast<unsigned char>(raw[10 + 1 + 3]), 10);
  EXPECT_EQ(static_cast<unsigned char>(raw[10 + 1 + 5]), 30);
  EXPECT_EQ(static_cast<unsigned char>(raw[1]), 255);
}

}  // namespace
}  // namespace mc::anim::tools
