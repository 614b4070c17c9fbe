// Both decoders must pass tests/proto/golden/frames_v1.json (the JavaScript
// one in js/decoder.test.mjs). This also pins the encoder: re-encoding the
// golden values must give the golden bytes, so a format change cannot slip
// in without a new version and new vectors.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "proto/frame_codec.hpp"
#include "proto/hello.hpp"

namespace mc::proto {
namespace {

using nlohmann::json;

json load() {
  std::ifstream in(std::string(MATCHCAST_SOURCE_DIR) + "/tests/proto/golden/frames_v1.json");
  std::stringstream ss;
  ss << in.rdbuf();
  return json::parse(ss.str());
}

std::string unhex(const std::string& h) {
  std::string out;
  for (std::size_t i = 0; i + 1 < h.size(); i += 2) out.push_back(static_cast<char>(std::stoi(h.substr(i, 2), nullptr, 16)));
  return out;
}

class Golden : public ::testing::Test {
 protected:
  void SetUp() override {
    golden = load();
    std::string error;
    ASSERT_TRUE(hello_from_json(golden.at("hello").dump(), hello, error)) << error;
  }
  json golden;
  Hello hello;
};

TEST_F(Golden, DecoderProducesTheExpectedValues) {
  FrameDecoder dec(hello.skeleton);
  for (const auto& f : golden.at("frames")) {
    PoseFrame out;
    std::string error;
    ASSERT_TRUE(dec.decode(unhex(f.at("hex").get<std::string>()), out, error)) << error;
    const json& e = f.at("expected");
    ASSERT_EQ(out.seq, e.at("seq").get<std::uint32_t>());
    EXPECT_EQ(out.time, e.at("time").get<int>());
    EXPECT_EQ(out.substep, e.at("substep").get<int>());
    EXPECT_EQ(out.server_time_ms, e.at("serverTimeMs").get<std::uint64_t>());
    EXPECT_EQ(static_cast<int>(out.play_mode), e.at("playMode").get<int>());
    EXPECT_EQ(out.score_left, e.at("scoreLeft").get<int>());
    EXPECT_NEAR(out.ball.x, e.at("ball").at("x").get<double>(), 1e-4);
    EXPECT_NEAR(out.ball.z, e.at("ball").at("z").get<double>(), 1e-4);
    for (std::size_t i = 0; i < out.players.size(); ++i) {
      const auto& p = out.players[i];
      const json& ep = e.at("players").at(i);
      EXPECT_EQ(static_cast<int>(p.side), ep.at("side").get<int>());
      EXPECT_EQ(p.unum, ep.at("unum").get<int>());
      EXPECT_EQ(p.state, ep.at("state").get<std::uint32_t>());
      EXPECT_NEAR(p.x, ep.at("x").get<double>(), 1e-4);
      EXPECT_NEAR(p.y, ep.at("y").get<double>(), 1e-4);
      EXPECT_NEAR(p.heading, ep.at("heading").get<double>(), 1e-4);
      for (int d = 0; d < hello.skeleton.dof_count(); ++d)
        ASSERT_NEAR(p.angles[static_cast<std::size_t>(d)], ep.at("angles").at(static_cast<std::size_t>(d)).get<double>(), 1e-4)
            << "frame " << out.seq << " player " << i << " dof " << d;
    }
  }
}

TEST_F(Golden, EncoderReproducesTheGoldenBytes) {
  FrameEncoder enc(hello.skeleton, {hello.keyframe_interval});
  FrameDecoder dec(hello.skeleton);
  for (const auto& f : golden.at("frames")) {
    const std::string bytes = unhex(f.at("hex").get<std::string>());
    PoseFrame decoded;
    std::string error;
    ASSERT_TRUE(dec.decode(bytes, decoded, error)) << error;
    bool key = false;
    EXPECT_EQ(enc.encode(decoded, key), bytes) << "frame " << decoded.seq;
    EXPECT_EQ(key, f.at("expected").at("keyframe").get<bool>());
  }
}

TEST_F(Golden, BadFramesAreRefusedWithTheExpectedError) {
  const auto& frames = golden.at("frames");
  for (const auto& b : golden.at("bad")) {
    FrameDecoder dec(hello.skeleton);
    PoseFrame out;
    std::string error;
    for (int i = 0; i < b.at("prefix").get<int>(); ++i)
      ASSERT_TRUE(dec.decode(unhex(frames.at(static_cast<std::size_t>(i)).at("hex").get<std::string>()), out, error));
    EXPECT_FALSE(dec.decode(unhex(b.at("hex").get<std::string>()), out, error)) << b.at("name");
    EXPECT_NE(error.find(b.at("error_contains").get<std::string>()), std::string::npos)
        << b.at("name") << ": " << error;
  }
}

}  // namespace
}  // namespace mc::proto
