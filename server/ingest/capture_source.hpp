// StateSource over a monitor capture file (tests/data/rcg/generated/
// mon19-*.dgrams.gz): every datagram a monitor received, replayed through
// the same MonitorStream the live client uses. Record format (little-endian):
// float64 unix_time, uint16 source_port, uint32 length, then the payload.
#pragma once

#include <memory>
#include <string>

#include "server/ingest/state_source.hpp"

namespace mc::ingest {

// nullptr + error when the file cannot be opened. Gzip is sniffed.
std::unique_ptr<StateSource> open_monitor_capture(const std::string& path, std::string& error);

}  // namespace mc::ingest
