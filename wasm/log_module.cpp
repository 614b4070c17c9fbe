// The WebAssembly module's C interface: one LogSession per opened log,
// driven by the page's worker (web/src/local/log_worker.js):
//
//   s = mc_open(keyframe_interval, lookahead, detail, base_ms, match_id)
//   loop: while mc_wants(s) > 0 and the file has more: copy a chunk to
//         mc_buffer(n), mc_input(s, n); at the file's end mc_end(s, why)
//         r = mc_step(s, states)        0 need input, 1 progress, 2 done, 3 failed
//         read mc_output(s) / mc_output_size(s), then mc_output_clear(s)
//   mc_status(s) -> JSON text (progress, outcome); mc_close(s)
//
// Pointers are offsets into the module's memory; strings are UTF-8, NUL-ended.
#include <emscripten/emscripten.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "wasm/log_session.hpp"

namespace {

// One staging buffer for input chunks, reused: the worker writes a chunk
// here, mc_input copies it into the session.
std::vector<char>& staging() {
  static std::vector<char> buf;
  return buf;
}

std::string& status_text() {
  static std::string text;
  return text;
}

mc::anim::DetailLevel detail_of(int level) {
  switch (level) {
    case 0: return mc::anim::DetailLevel::None;
    case 1: return mc::anim::DetailLevel::Run;
    case 2: return mc::anim::DetailLevel::Kick;
    default: return mc::anim::DetailLevel::Full;
  }
}

}  // namespace

extern "C" {

EMSCRIPTEN_KEEPALIVE void* mc_open(int keyframe_interval, int lookahead, int detail, double base_ms,
                                   const char* match_id) {
  mc::wasm::LogSessionOptions o;
  if (keyframe_interval > 0) o.pipeline.keyframe_interval = keyframe_interval;
  if (lookahead > 0) o.pipeline.anim.lookahead_cycles = lookahead;
  o.pipeline.anim.detail = detail_of(detail);
  o.server_time_base_ms = base_ms > 0 ? static_cast<std::uint64_t>(base_ms) : 0;
  o.match_id = match_id ? match_id : "";
  return new mc::wasm::LogSession(std::move(o));
}

EMSCRIPTEN_KEEPALIVE void mc_close(void* s) { delete static_cast<mc::wasm::LogSession*>(s); }

EMSCRIPTEN_KEEPALIVE char* mc_buffer(int n) {
  auto& buf = staging();
  if (n > 0 && buf.size() < static_cast<std::size_t>(n)) buf.resize(static_cast<std::size_t>(n));
  return buf.data();
}

EMSCRIPTEN_KEEPALIVE void mc_input(void* s, int n) {
  if (n <= 0 || static_cast<std::size_t>(n) > staging().size()) return;
  static_cast<mc::wasm::LogSession*>(s)->input(std::string_view(staging().data(), static_cast<std::size_t>(n)));
}

EMSCRIPTEN_KEEPALIVE void mc_end(void* s, const char* error) {
  static_cast<mc::wasm::LogSession*>(s)->end_input(error ? error : "");
}

EMSCRIPTEN_KEEPALIVE int mc_wants(void* s) {
  return static_cast<int>(static_cast<mc::wasm::LogSession*>(s)->wants());
}

EMSCRIPTEN_KEEPALIVE int mc_step(void* s, int max_states) {
  return static_cast<int>(static_cast<mc::wasm::LogSession*>(s)->step(max_states));
}

EMSCRIPTEN_KEEPALIVE const char* mc_output(void* s) {
  return static_cast<mc::wasm::LogSession*>(s)->output().data();
}

EMSCRIPTEN_KEEPALIVE int mc_output_size(void* s) {
  return static_cast<int>(static_cast<mc::wasm::LogSession*>(s)->output().size());
}

EMSCRIPTEN_KEEPALIVE void mc_output_clear(void* s) { static_cast<mc::wasm::LogSession*>(s)->clear_output(); }

EMSCRIPTEN_KEEPALIVE const char* mc_status(void* s) {
  status_text() = static_cast<mc::wasm::LogSession*>(s)->status_json();
  return status_text().c_str();
}

}  // extern "C"
