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

bool inflate_text(std::string_view in, std::size_t size, std::string& out) {
  z_stream z{};
  if (inflateInit2(&z, -15) != Z_OK) return false;
  const std::string_view dict = control_dictionary();
  bool ok = inflateSetDictionary(&z, reinterpret_cast<const Bytef*>(dict.data()), static_cast<uInt>(dict.size())) == Z_OK;
  out.assign(size, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  // Exactly `size` bytes, the end of the stream, and no input left over.
  ok = ok && inflate(&z, Z_FINISH) == Z_STREAM_END && z.total_out == size && z.avail_in == 0;
  inflateEnd(&z);
  return ok;
}

}  // namespace mc::proto::rec
