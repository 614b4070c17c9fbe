// CPU time and resident memory of a process, read from /proc (Linux).
#pragma once

#include <sys/types.h>

namespace mc::loadgen {

struct ProcSample {
  double cpu_seconds = 0;  // user + system
  long rss_kb = 0;
};

// False when the process does not exist or /proc cannot be read.
bool sample_process(pid_t pid, ProcSample& out);

}  // namespace mc::loadgen
