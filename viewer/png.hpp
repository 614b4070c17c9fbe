// Minimal PNG files (8-bit RGB, no interlace) for --screenshot and for the
// tests that read the screenshots back. zlib does the compression; no image
// library is in the dependency list for this one need.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace mc::viewer {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3, rows top to bottom
  const std::uint8_t* at(int x, int y) const { return &rgb[(static_cast<std::size_t>(y) * width + x) * 3]; }
};

bool write_png(const std::string& path, const Image& image, std::string& error);
// Reads the PNGs write_png writes (8-bit RGB or RGBA, any filter); false +
// error for anything else or a damaged file.
bool read_png(const std::string& path, Image& out, std::string& error);

}  // namespace mc::viewer
