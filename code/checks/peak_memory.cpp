// The process's peak resident memory, read from /proc/self/status.
#include "peak_memory.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace dt {

long peakResidentKB() {
  std::FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return 0;
  char line[256];
  long kb = 0;
  while (std::fgets(line, sizeof line, f))
    if (std::strncmp(line, "VmHWM:", 6) == 0) kb = std::atol(line + 6);
  std::fclose(f);
  return kb;
}

}  // namespace dt
