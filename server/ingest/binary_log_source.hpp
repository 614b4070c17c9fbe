// StateSource for binary game logs: v1 (no header, 2052-byte dispinfo_t
// records), v2 ("ULG\x02", showinfo_t shows) and v3 ("ULG\x03", parameter,
// play-mode, team and short_showinfo_t2 records). rcss-protocol.md section 6.
#pragma once

#include <memory>

#include "server/ingest/byte_source.hpp"
#include "server/ingest/log_format.hpp"
#include "server/ingest/state_source.hpp"

namespace mc::ingest {

// `format` is BinaryV1, BinaryV2 or BinaryV3; `src` starts at byte 0.
std::unique_ptr<StateSource> make_binary_log_source(std::unique_ptr<ByteSource> src,
                                                    LogFormat format);

}  // namespace mc::ingest
