// libFuzzer target: every triangulation method on point sets decoded from the bytes, each
// result checked exactly (see fuzz_checks.h).
#include <cstdio>
#include <cstdlib>

#include "fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string e = dtfuzz::checkPointSet(dtfuzz::decodePoints(data, size));
  if (!e.empty()) {
    std::fprintf(stderr, "fuzz_triangulate: %s\n", e.c_str());
    std::abort();
  }
  return 0;
}
