// A tiny PNG encoder (8-bit RGB, one zlib-compressed IDAT) for the quality
// tool's pictures.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace mc::anim::tools {

// An RGB image, rows top to bottom, 3 bytes per pixel.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  Image(int w, int h, std::uint8_t grey = 255)
      : width(w), height(h), rgb(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3, grey) {}
  void set(int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
    rgb[i] = r; rgb[i + 1] = g; rgb[i + 2] = b;
  }
};

// The PNG file bytes of `img`.
std::string encode_png(const Image& img);
// Writes `img` to `path`; false (with `error` set) when the file cannot be written.
bool write_png(const std::string& path, const Image& img, std::string& error);

}  // namespace mc::anim::tools
