#include "anim/tools/png.hpp"

#include <png.h>

#include <cstdio>
#include <memory>

namespace mc::anim::tools {
namespace {

bool valid(const Image& img, std::string& error) {
  if (img.width <= 0 || img.height <= 0 ||
      img.rgb.size() != static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height) * 3) {
    error = "png: the image's pixels do not match its size";
    return false;
  }
  return true;
}

// libpng's simplified API, 8-bit sRGB without alpha.
png_image describe(const Image& img) {
  png_image p{};
  p.version = PNG_IMAGE_VERSION;
  p.width = static_cast<png_uint_32>(img.width);
  p.height = static_cast<png_uint_32>(img.height);
  p.format = PNG_FORMAT_RGB;
  return p;
}

}  // namespace

std::string encode_png(const Image& img, std::string& error) {
  if (!valid(img, error)) return {};
  png_image p = describe(img);
  png_alloc_size_t size = 0;
  // First call measures, second writes.
  if (!png_image_write_to_memory(&p, nullptr, &size, 0, img.rgb.data(), 0, nullptr)) {
    error = std::string("png: ") + p.message;
    return {};
  }
  std::string out(size, '\0');
  if (!png_image_write_to_memory(&p, out.data(), &size, 0, img.rgb.data(), 0, nullptr)) {
    error = std::string("png: ") + p.message;
    return {};
  }
  out.resize(size);
  return out;
}

std::string encode_png(const Image& img) {
  std::string error;
  return encode_png(img, error);
}

bool write_png(const std::string& path, const Image& img, std::string& error) {
  const std::string bytes = encode_png(img, error);
  if (bytes.empty()) return false;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "wb"), &std::fclose);
  if (!f || std::fwrite(bytes.data(), 1, bytes.size(), f.get()) != bytes.size() || std::fflush(f.get()) != 0) {
    error = "cannot write " + path;
    return false;
  }
  return true;
}

bool read_png(const std::string& path, Image& out, std::string& error) {
  png_image p{};
  p.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&p, path.c_str())) {
    error = path + ": " + p.message;
    return false;
  }
  p.format = PNG_FORMAT_RGB;
  Image img(static_cast<int>(p.width), static_cast<int>(p.height), std::vector<std::uint8_t>(PNG_IMAGE_SIZE(p)));
  const png_color black{0, 0, 0};
  if (!png_image_finish_read(&p, &black, img.rgb.data(), 0, nullptr)) {
    error = path + ": " + p.message;
    png_image_free(&p);
    return false;
  }
  out = std::move(img);
  return true;
}

}  // namespace mc::anim::tools
