// RGB images and their PNG files, through libpng: the one PNG reader and
// writer of the project (the quality and mocap tools' figures, the native
// viewer's screenshots and the tests that read them back).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace mc::anim::tools {

// An RGB image, rows top to bottom, 3 bytes per pixel.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;

  Image() = default;
  Image(int w, int h, std::uint8_t grey = 255)
      : width(w), height(h), rgb(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3, grey) {}
  Image(int w, int h, std::vector<std::uint8_t> pixels) : width(w), height(h), rgb(std::move(pixels)) {}

  void set(int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    std::uint8_t* p = &rgb[index(x, y)];
    p[0] = r; p[1] = g; p[2] = b;
  }
  const std::uint8_t* at(int x, int y) const { return &rgb[index(x, y)]; }

 private:
  std::size_t index(int x, int y) const {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
  }
};

// The PNG file bytes of `img`; empty (with `error` set) for an image whose
// pixel count does not match its size.
std::string encode_png(const Image& img, std::string& error);
std::string encode_png(const Image& img);
// Writes `img` to `path`; false (with `error` set) when it cannot.
bool write_png(const std::string& path, const Image& img, std::string& error);
// Reads any PNG libpng reads (any depth, palette, alpha, interlace) as 8-bit
// RGB (alpha composited on black); false with `error` for a damaged file.
bool read_png(const std::string& path, Image& out, std::string& error);

}  // namespace mc::anim::tools
