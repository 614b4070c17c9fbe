#include "proto/text_deflate.hpp"

#include <zlib.h>

namespace mc::proto::rec {

std::string_view control_dictionary() {
  // Least common first: deflate reaches the end of the dictionary with the
  // shortest distances.
  static constexpr char kDictionary[] =
      R"({"type":"feed","status":"lost","seq":0,"server_time_ms":1763785000000,"detail":""})"
      R"({"type":"teams","seq":0,"left":{"name":"","color":"#ffd700","color2":"#000000"},"right":{"name":"")"
      R"({"card":"yellow","seq":0,"side":"right","time":0,"type":"card","unum":2})"
      R"({"left":0,"pen_left":0,"pen_right":0,"right":1,"seq":0,"time":0,"type":"score"})"
      R"({"score":[0,1],"seq":0,"side":"left","time":0,"type":"goal"})"
      R"({"mode":"free_kick_l","mode_id":8,"seq":0,"time":0,"type":"play_mode"})"
      R"({"mode":"kick_in_r","mode_id":7,"seq":0,"time":0,"type":"play_mode"})"
      R"({"left":[8000,7743,7498,7869,7674,6980,7404,7500,7210,7176,7450],"right":[8000,7539,7467,7480,7241,7000,7029,7300,7935,6932,7100],"seq":0,"time":0,"type":"stamina"})"
      R"({"contact_time_ms":313250,"foot":"left","seq":0,"side":"right","time":0,"type":"kick","unum":10})"
      R"({"contact_time_ms":313250,"foot":"right","seq":0,"side":"left","time":0,"type":"kick","unum":11})";
  return {kDictionary, sizeof kDictionary - 1};
}

std::string deflate_text(std::string_view text) {
  z_stream z{};
  // Raw deflate (negative window bits): the chunk's CRC already checks it.
  if (deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, -15, 9, Z_DEFAULT_STRATEGY) != Z_OK) return {};
  const std::string_view dict = control_dictionary();
  deflateSetDictionary(&z, reinterpret_cast<const Bytef*>(dict.data()), static_cast<uInt>(dict.size()));
  std::string out(deflateBound(&z, static_cast<uLong>(text.size())), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
  z.avail_in = static_cast<uInt>(text.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int rc = deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  return rc == Z_STREAM_END ? out : std::string();
}

namespace {

// One raw inflater per thread, reset for each chunk: inflateInit2 and
// inflateEnd allocate and free ~40 KB (state and window) each time, and a
// replay loads a chunk a second per spectator, a seek one or two more.
class Inflater {
 public:
  Inflater() { ok_ = inflateInit2(&z_, -15) == Z_OK; }
  ~Inflater() {
    if (ok_) inflateEnd(&z_);
  }
  Inflater(const Inflater&) = delete;
  Inflater& operator=(const Inflater&) = delete;
  // A stream ready for the next chunk, or null if zlib could not start one.
  z_stream* fresh() { return ok_ && inflateReset(&z_) == Z_OK ? &z_ : nullptr; }

 private:
  z_stream z_{};
  bool ok_ = false;
};

}  // namespace

bool inflate_text(std::string_view in, std::size_t size, std::string& out) {
  thread_local Inflater inflater;
  z_stream* z = inflater.fresh();
  if (!z) return false;
  const std::string_view dict = control_dictionary();
  bool ok = inflateSetDictionary(z, reinterpret_cast<const Bytef*>(dict.data()), static_cast<uInt>(dict.size())) == Z_OK;
  out.assign(size, '\0');
  z->next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  z->avail_in = static_cast<uInt>(in.size());
  z->next_out = reinterpret_cast<Bytef*>(out.data());
  z->avail_out = static_cast<uInt>(out.size());
  // Exactly `size` bytes, the end of the stream, and no input left over.
  return ok && inflate(z, Z_FINISH) == Z_STREAM_END && z->total_out == size && z->avail_in == 0;
}

}  // namespace mc::proto::rec
