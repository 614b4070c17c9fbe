// What the server's pipeline makes of a log file, in LogSession's output
// format: the reference the WebAssembly module is compared with (natively
// only: it reads the file with the server's reader, gzip through zlib).
#pragma once

#include <string>

#include "wasm/log_session.hpp"

namespace mc::wasm {

// Reads `path` with ingest::open_log, runs app::BroadcastPipeline over every
// state with the options' clock and match id, and appends the records to
// `out`. False with `error` when the file cannot be read or holds no state.
bool broadcast_log_file(const std::string& path, const LogSessionOptions& options, std::string& out,
                        std::string& error);

}  // namespace mc::wasm
