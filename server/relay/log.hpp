// Structured logs: one JSON object per line on stderr, so that both a person
// (`grep`) and a log shipper can read them.
#pragma once

#include <string_view>

namespace mc::relay {

// {"ts":"2026-11-22T03:50:00.123Z","event":EVENT,"detail":DETAIL}
void log_event(std::string_view event, std::string_view detail = {});

}  // namespace mc::relay
