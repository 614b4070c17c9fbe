#include "anim/tools/png.hpp"

#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

namespace mc::anim::tools {
namespace {

Image gradient(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      img.set(x, y, static_cast<std::uint8_t>(x * 40), static_cast<std::uint8_t>(y * 70), static_cast<std::uint8_t>((x + y) * 13));
  return img;
}

TEST(Png, WritesWhatItReadsBack) {
  const Image image = gradient(7, 3);
  const std::string path = testing::TempDir() + "/anim_png_test.png";
  std::string error;
  ASSERT_TRUE(write_png(path, image, error)) << error;
  Image back;
  ASSERT_TRUE(read_png(path, back, error)) << error;
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.rgb, image.rgb);
  EXPECT_EQ(back.at(6, 2)[0], 240);
  std::remove(path.c_str());
}

TEST(Png, EncodesAFileWithThePngSignatureAndSize) {
  const std::string png = encode_png(gradient(3, 2));
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(png.substr(12, 4), "IHDR");
  EXPECT_EQ(static_cast<unsigned char>(png[19]), 3);  // width, big-endian
  EXPECT_EQ(static_cast<unsigned char>(png[23]), 2);  // height
}

TEST(Png, RefusesWhatIsNotAnImage) {
  std::string error;
  Image bad(4, 4);
  bad.rgb.pop_back();
  EXPECT_TRUE(encode_png(bad, error).empty());
  EXPECT_NE(error.find("do not match"), std::string::npos);
  EXPECT_FALSE(write_png(testing::TempDir() + "/never.png", Image{}, error));

  // Not a PNG, a truncated PNG, a missing file: a clear error each, no crash.
  const std::string text = testing::TempDir() + "/anim_png_text.png";
  std::ofstream(text) << "this is not a picture";
  Image back;
  EXPECT_FALSE(read_png(text, back, error));
  EXPECT_NE(error.find(text), std::string::npos) << error;
  const std::string whole = encode_png(gradient(50, 50));
  const std::string cut = testing::TempDir() + "/anim_png_cut.png";
  std::ofstream(cut, std::ios::binary) << whole.substr(0, whole.size() / 2);
  EXPECT_FALSE(read_png(cut, back, error));
  EXPECT_FALSE(read_png("/nonexistent.png", back, error));
  EXPECT_FALSE(error.empty());
  std::remove(text.c_str());
  std::remove(cut.c_str());
}

}  // namespace
}  // namespace mc::anim::tools
