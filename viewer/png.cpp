#include "viewer/png.hpp"

#include <cstdlib>
#include <fstream>
#include <iterator>

#include <zlib.h>

namespace mc::viewer {
namespace {

const char kSignature[] = "\x89PNG\r\n\x1a\n";

void put32(std::string& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<char>((v >> s) & 0xff));
}

std::uint32_t get32(const std::string& in, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(in[at + i]);
  return v;
}

void chunk(std::string& out, const char* type, const std::string& data) {
  put32(out, static_cast<std::uint32_t>(data.size()));
  const std::string body = std::string(type, 4) + data;
  out += body;
  put32(out, static_cast<std::uint32_t>(
                 crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()))));
}

int paeth(int a, int b, int c) {
  const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  return (pa <= pb && pa <= pc) ? a : (pb <= pc ? b : c);
}

}  // namespace

bool write_png(const std::string& path, const Image& image, std::string& error) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
    error = "write_png: bad image size";
    return false;
  }
  std::string raw;
  const std::size_t row = static_cast<std::size_t>(image.width) * 3;
  for (int y = 0; y < image.height; ++y) {
    raw.push_back('\0');  // filter: none
    raw.append(reinterpret_cast<const char*>(&image.rgb[y * row]), row);
  }
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::string packed(size, '\0');
  if (compress2(reinterpret_cast<Bytef*>(packed.data()), &size, reinterpret_cast<const Bytef*>(raw.data()),
                static_cast<uLong>(raw.size()), 6) != Z_OK) {
    error = "write_png: zlib failed";
    return false;
  }
  packed.resize(size);
  std::string out(kSignature, 8), ihdr;
  put32(ihdr, static_cast<std::uint32_t>(image.width));
  put32(ihdr, static_cast<std::uint32_t>(image.height));
  ihdr += std::string("\x08\x02\x00\x00\x00", 5);  // 8-bit, RGB, deflate, filter 0, no interlace
  chunk(out, "IHDR", ihdr);
  chunk(out, "IDAT", packed);
  chunk(out, "IEND", "");
  std::ofstream file(path, std::ios::binary);
  file.write(out.data(), static_cast<std::streamsize>(out.size()));
  if (!file) {
    error = "cannot write " + path;
    return false;
  }
  return true;
}

bool read_png(const std::string& path, Image& out, std::string& error) {
  std::ifstream file(path, std::ios::binary);
  const std::string in((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (in.size() < 8 || in.compare(0, 8, std::string(kSignature, 8)) != 0) {
    error = path + ": not a PNG file";
    return false;
  }
  std::string idat;
  int width = 0, height = 0, channels = 0;
  for (std::size_t at = 8; at + 12 <= in.size();) {
    const std::uint32_t len = get32(in, at);
    if (len > in.size() - at - 12) break;
    const std::string type = in.substr(at + 4, 4);
    if (type == "IHDR" && len >= 13) {
      width = static_cast<int>(get32(in, at + 8));
      height = static_cast<int>(get32(in, at + 12));
      const int depth = static_cast<unsigned char>(in[at + 16]), color = static_cast<unsigned char>(in[at + 17]);
      channels = color == 2 ? 3 : (color == 6 ? 4 : 0);
      if (depth != 8 || channels == 0 || in[at + 20] != 0) {
        error = path + ": only 8-bit RGB/RGBA non-interlaced PNGs are read";
        return false;
      }
    } else if (type == "IDAT") {
      idat += in.substr(at + 8, len);
    }
    at += 12 + len;
  }
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384) {
    error = path + ": no usable IHDR";
    return false;
  }
  const std::size_t stride = static_cast<std::size_t>(width) * channels;
  std::string raw((stride + 1) * height, '\0');
  uLongf size = static_cast<uLongf>(raw.size());
  if (uncompress(reinterpret_cast<Bytef*>(raw.data()), &size, reinterpret_cast<const Bytef*>(idat.data()),
                 static_cast<uLong>(idat.size())) != Z_OK ||
      size != raw.size()) {
    error = path + ": damaged image data";
    return false;
  }
  std::vector<std::uint8_t> cur(stride), prev(stride, 0);
  out.width = width;
  out.height = height;
  out.rgb.assign(static_cast<std::size_t>(width) * height * 3, 0);
  for (int y = 0; y < height; ++y) {
    const int filter = static_cast<unsigned char>(raw[y * (stride + 1)]);
    const auto* src = reinterpret_cast<const std::uint8_t*>(&raw[y * (stride + 1) + 1]);
    for (std::size_t i = 0; i < stride; ++i) {
      const int a = i >= static_cast<std::size_t>(channels) ? cur[i - channels] : 0, b = prev[i],
                c = i >= static_cast<std::size_t>(channels) ? prev[i - channels] : 0;
      int v = src[i];
      if (filter == 1) v += a;
      else if (filter == 2) v += b;
      else if (filter == 3) v += (a + b) / 2;
      else if (filter == 4) v += paeth(a, b, c);
      else if (filter != 0) {
        error = path + ": bad PNG filter";
        return false;
      }
      cur[i] = static_cast<std::uint8_t>(v);
    }
    for (int x = 0; x < width; ++x)
      for (int k = 0; k < 3; ++k) out.rgb[(static_cast<std::size_t>(y) * width + x) * 3 + k] = cur[x * channels + k];
    prev.swap(cur);
  }
  return true;
}

}  // namespace mc::viewer
