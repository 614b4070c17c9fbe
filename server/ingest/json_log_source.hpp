// StateSource for JSON game logs (19.x array; 17.x "ULG6"+array and 18.x
// "JSON"+array flavours tolerated), streamed element by element.
#pragma once

#include <memory>

#include "server/ingest/byte_source.hpp"
#include "server/ingest/state_source.hpp"

namespace mc::ingest {

std::unique_ptr<StateSource> make_json_log_source(std::unique_ptr<ByteSource> src);

}  // namespace mc::ingest
