// libFuzzer target: the JSON messages a spectator sends, as the server reads
// them: the session's reading (relay/spectator_message.hpp: time shift or
// replay) and a replay player steered by them (pause, play, seek, speed,
// goals) over a recording. The input is up to 8 messages, one a line,
// given to a player in order as the session routes them
// (relay/websocket_session.cpp, on_text): a replay's player reads the
// messages of type "replay"; a time-shifted spectator's player gets those
// too, and each time-shift seek as a replay seek, until "live" ends it.
// Must never crash, hang or read out of bounds (ASan/UBSan); ignoring a
// message is fine.
#include <sys/mman.h>
#include <unistd.h>

#include <boost/asio/io_context.hpp>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "server/record/recording_reader.hpp"
#include "server/relay/spectator_message.hpp"
#include "server/replay/replay_player.hpp"

namespace {

// The golden recording (10+ frames, a kick and a goal), read once into
// memory; each input gets a reader of its own over it. Its hello is parsed
// once, here, and given to every input's reader, as the relay's catalog
// does for the replays of one file (parsing it made up about half of an
// input's time): the file never changes, so the reader's check that the
// hello text is the same always passes.
struct Fixture {
  std::string path;
  mc::replay::RecordingSummary summary;
  std::shared_ptr<const mc::record::RecordingHello> hello;
  Fixture() {
    std::ifstream in(std::string(MATCHCAST_SOURCE_DIR) + "/tests/proto/golden/recording_v3.mcrec", std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const int fd = ::memfd_create("spectator-fuzz", MFD_CLOEXEC);
    if (fd < 0 || ::write(fd, bytes.data(), bytes.size()) != static_cast<ssize_t>(bytes.size())) std::abort();
    path = "/proc/self/fd/" + std::to_string(fd);
    mc::record::RecordingReader reader;
    std::string error;
    if (!reader.open(path, error) || !mc::replay::summarize(reader, summary, error)) std::abort();
    hello = reader.shared_hello();
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Fixture fx;
  static boost::asio::io_context ioc;
  // A fresh player (its own reader, encoder and channel) for every input,
  // playing from the start at speed 1: nothing of one input's steering
  // (position, pause, speed, the channel's kept messages) reaches the next,
  // so a crashing input replays alone. Odd sizes use the follow (time
  // shift) mode.
  const bool follow = (size & 1) != 0;
  // The session's reading and routing first: an input none of whose lines
  // reaches the player gives it nothing to do, and making one (a reader, a
  // channel) to start and close it would be most of such an input's time.
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  std::vector<mc::relay::SpectatorMessage> messages;
  std::size_t pos = 0;
  for (int n = 0; n < 8 && pos <= input.size(); ++n) {
    std::size_t end = input.find('\n', pos);
    if (end == std::string_view::npos) end = input.size();
    auto m = mc::relay::read_spectator_message(input.substr(pos, end - pos));
    pos = end + 1;
    if (!m) continue;
    if (m->type == "replay") {
      messages.push_back(std::move(*m));
    } else if (follow && m->type == "timeshift" && m->action == "seek" && m->time) {
      messages.push_back(mc::relay::SpectatorMessage{"replay", "seek", *m->time, std::nullopt});
    } else if (follow && m->type == "timeshift" && m->action == "live") {
      break;  // back to the live channel: the session closes the player
    }
  }
  if (messages.empty()) return 0;
  std::shared_ptr<mc::replay::ReplayPlayer> player;
  {
    auto reader = std::make_unique<mc::record::RecordingReader>();
    std::string error;
    if (!reader->open(fx.path, error, fx.hello)) std::abort();
    player = std::make_shared<mc::replay::ReplayPlayer>(ioc.get_executor(), "fuzz.mcrec", std::move(reader),
                                                        fx.summary, follow);
    player->start();
  }
  for (const auto& m : messages) player->on_message(m);
  ioc.restart();
  ioc.poll();  // ready handlers only: the next frame's timer is 50 ms away at the least
  player->close();
  ioc.restart();
  ioc.poll();  // the cancelled timer's handler, which holds the player
  return 0;
}
