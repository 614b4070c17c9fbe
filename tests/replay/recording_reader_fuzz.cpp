// libFuzzer target: the recording reader (server/record) on untrusted files,
// as the relay's replay and the native viewer open them: open (header,
// hello, index or the scan that rebuilds it), every frame in order, seeks,
// refresh and rewind. The first byte picks what the rest of the input is:
//   0  a whole file
//   1  what follows a valid file header and hello (chunks, an index, junk)
//   2  the index and trailer of a valid file whose chunks are real
//   3  a real file with the input written over it at an offset
// Must never crash, hang or read out of bounds (ASan/UBSan); refusing is fine.
// The file lives in memory (memfd): no disk I/O per input.
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "proto/recording.hpp"
#include "server/record/recording_reader.hpp"

namespace {

namespace rec = mc::proto::rec;

struct Fixture {
  int fd = -1;
  std::string path;
  std::string real;     // a real recording (the seed 0-closed: half a second of the bundled game)
  std::string prefix;   // its file header and hello record
  std::string chunks;   // prefix + its chunk records, without index and trailer
  // The real file's hello, parsed once: every input's reader gets it, and
  // takes it only where the input's hello text is byte for byte the same
  // (modes 1-3, and whole files that kept it); any other hello is parsed.
  // Parsing this one again was ~95% of each open().
  std::shared_ptr<const mc::record::RecordingHello> parsed_hello;
  Fixture() {
    fd = ::memfd_create("mcrec-fuzz", MFD_CLOEXEC);
    path = "/proc/self/fd/" + std::to_string(fd);
    std::ifstream in(std::string(MATCHCAST_SOURCE_DIR) + "/tests/replay/fuzz/seeds/recording_reader/0-closed",
                     std::ios::binary);
    real.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (!real.empty()) real.erase(0, 1);  // the seed's mode byte
    if (real.size() < rec::kFileHeaderSize + 4) std::abort();  // the fixture must be there
    const std::size_t hello = rec::record_size_hint(std::string_view(real).substr(rec::kFileHeaderSize));
    prefix = real.substr(0, rec::kFileHeaderSize + hello);
    std::uint64_t index_offset = 0;
    if (!rec::parse_trailer(std::string_view(real).substr(real.size() - rec::kTrailerSize), index_offset)) std::abort();
    chunks = real.substr(0, index_offset);
    put(real);
    mc::record::RecordingReader reader;
    std::string error;
    if (!reader.open(path, error)) std::abort();
    parsed_hello = reader.shared_hello();
  }
  void put(const std::string& bytes) const {
    if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, bytes.data(), bytes.size(), 0) != static_cast<ssize_t>(bytes.size()))
      std::abort();
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Fixture fx;
  if (size == 0) return 0;
  const std::string input(reinterpret_cast<const char*>(data + 1), size - 1);
  std::string file;
  switch (data[0] % 4) {
    case 0: file = input; break;
    case 1: file = fx.prefix + input; break;
    case 2: file = fx.chunks + input; break;
    default: {
      file = fx.real;
      const std::size_t at = input.size() >= 2 ? (static_cast<std::uint8_t>(input[0]) | static_cast<std::uint8_t>(input[1]) << 8) % file.size() : 0;
      file.replace(at, std::min(input.size(), file.size() - at), input);
      break;
    }
  }
  fx.put(file);

  // The reader's own work (records, index, scan, chunks, seeking) on every
  // input; the frames' decoding only as far as a few frames: the codec is
  // linked uninstrumented here (tests/replay/CMakeLists.txt), and
  // proto_frame_decoder_fuzz fuzzes it.
  mc::record::RecordingReader reader;
  std::string error;
  if (!reader.open(fx.path, error, fx.parsed_hello)) return 0;
  mc::PoseFrame f;
  std::vector<std::string> controls;
  for (int i = 0; i < 3 && reader.next(f, error, &controls); ++i) {
  }
  reader.refresh(error);
  (void)reader.frame_count();
  if (!reader.chunks().empty()) {
    const auto& chunks = reader.chunks();
    const int t = chunks[(size + data[0]) % chunks.size()].first_time + static_cast<int>(size % 7) - 3;
    if (reader.seek(t, f, error)) reader.next(f, error);
  }
  return 0;
}
