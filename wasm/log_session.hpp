// One log opened in the page: decoded bytes in (as they arrive), the
// broadcast out (hello, encoded frames, control messages), step by step so
// that the Web Worker running it can take more input and pass frames on
// between steps. It is the server's pipeline (server/ingest's readers,
// server/app's BroadcastPipeline) with memory input and a made-up clock:
// frame n is stamped server_time_base_ms + 50 n, so that the output is a
// pure function of the log and the options.
//
// Output records, appended to output() until clear_output():
//   u8 kind, u32 length (little-endian), `length` bytes
//   kind 'h': the hello (JSON)   'k': a keyframe   'f': a delta frame
//        'c': a control message (JSON)
// Frames and messages come in wire order, as a relay sends them.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "server/app/broadcast_pipeline.hpp"
#include "server/ingest/log_format.hpp"
#include "server/ingest/state_source.hpp"
#include "wasm/push_byte_source.hpp"

namespace mc::wasm {

// Appends one output record: kind, u32 little-endian length, the bytes.
void put_record(std::string& out, char kind, std::string_view bytes);

struct LogSessionOptions {
  app::PipelineOptions pipeline;          // keyframe interval, animation settings
  std::uint64_t server_time_base_ms = 0;  // server time of frame 0
  std::string match_id;                   // the hello's match_id (the file name)
  // Unread bytes the reader needs before it may run (or the end of input):
  // more than any stretch of a log between two states (a team's logo is
  // the largest, a few hundred KB), so that it never meets a false end.
  std::size_t margin_bytes = 4u << 20;
  // A game is about 6,000 states (10 Hz); past this the rest of the file is
  // not read (a huge or endless file cannot use up the page's memory).
  std::uint64_t max_states = 40000;
};

class LogSession {
 public:
  explicit LogSession(LogSessionOptions options);
  ~LogSession();

  // Decoded log bytes (the page inflates gzip), in order.
  void input(std::string_view bytes) { in_.append(bytes); }
  // The end of the input; `error` says why it ended early ("" = the file's end).
  void end_input(std::string error = {}) { in_.end(std::move(error)); }
  // Bytes to append before step() can go on (0 when it can).
  std::size_t wants() const;

  enum class Status { NeedInput, Progress, Done, Failed };
  // Reads up to `max_states` states, animates and encodes them into output().
  // NeedInput: append more (or end the input); Progress: call again; Done:
  // the whole log went out; Failed: error() says why (what was read before
  // went out and stays valid).
  Status step(int max_states);

  const std::string& output() const { return out_; }
  void clear_output() { out_.clear(); }

  // Progress and outcome as one JSON object: states, frames, bytes read,
  // last cycle, format, skipped records and their first messages, and on
  // failure or early end "error" / "ended_early".
  std::string status_json() const;
  const std::string& error() const { return error_; }

 private:
  bool open_reader();
  void fail(std::string why);
  void finish();
  void emit();  // the pipeline's waiting frames and messages into out_
  void put(char kind, std::string_view bytes);

  LogSessionOptions options_;
  PushByteSource in_;
  std::unique_ptr<ingest::StateSource> source_;
  std::unique_ptr<app::BroadcastPipeline> pipeline_;
  ingest::LogFormat format_ = ingest::LogFormat::Unknown;
  std::string out_;
  std::string error_;
  bool done_ = false, failed_ = false, capped_ = false;
  std::uint64_t states_ = 0;
  int last_time_ = 0;
};

}  // namespace mc::wasm
