#include "anim/tools/png_writer.hpp"

#include <fstream>

#include <zlib.h>

namespace mc::anim::tools {
namespace {

void put32(std::string& s, std::uint32_t v) {
  s.push_back(static_cast<char>(v >> 24));
  s.push_back(static_cast<char>(v >> 16));
  s.push_back(static_cast<char>(v >> 8));
  s.push_back(static_cast<char>(v));
}

// length, type, data, CRC over type and data (PNG spec section 5.3).
void chunk(std::string& out, const char* type, const std::string& data) {
  put32(out, static_cast<std::uint32_t>(data.size()));
  const std::string body = std::string(type, 4) + data;
  out += body;
  put32(out, static_cast<std::uint32_t>(
                 crc32(0L, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()))));
}

}  // namespace

std::string encode_png(const Image& img) {
  std::string out("\x89PNG\r\n\x1a\n", 8);
  std::string ihdr;
  put32(ihdr, static_cast<std::uint32_t>(img.width));
  put32(ihdr, static_cast<std::uint32_t>(img.height));
  ihdr += std::string("\x08\x02\x00\x00\x00", 5);  // 8 bit, RGB, deflate, no filter, no interlace
  chunk(out, "IHDR", ihdr);
  // Each row starts with filter type 0 (none).
  std::string raw;
  const std::size_t row = static_cast<std::size_t>(img.width) * 3;
  raw.reserve((row + 1) * static_cast<std::size_t>(img.height));
  for (int y = 0; y < img.height; ++y) {
    raw.push_back('\0');
    raw.append(reinterpret_cast<const char*>(img.rgb.data()) + row * static_cast<std::size_t>(y), row);
  }
  uLongf len = compressBound(static_cast<uLong>(raw.size()));
  std::string z(len, '\0');
  compress2(reinterpret_cast<Bytef*>(z.data()), &len, reinterpret_cast<const Bytef*>(raw.data()),
            static_cast<uLong>(raw.size()), 6);
  z.resize(len);
  chunk(out, "IDAT", z);
  chunk(out, "IEND", "");
  return out;
}

bool write_png(const std::string& path, const Image& img, std::string& error) {
  std::ofstream f(path, std::ios::binary);
  if (!f) { error = "cannot open " + path; return false; }
  const std::string bytes = encode_png(img);
  f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!f) { error = "cannot write " + path; return false; }
  return true;
}

}  // namespace mc::anim::tools
