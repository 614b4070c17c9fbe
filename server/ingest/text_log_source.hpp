// StateSource for text game logs ULG4, ULG5 and ULG6 (rcssserver 12..19),
// streamed line by line from a ByteSource (plain or gzip).
#pragma once

#include <memory>

#include "server/ingest/byte_source.hpp"
#include "server/ingest/state_source.hpp"

namespace mc::ingest {

// Takes ownership of `src`, which must start at the "ULGn" header line.
std::unique_ptr<StateSource> make_text_log_source(std::unique_ptr<ByteSource> src);

}  // namespace mc::ingest
