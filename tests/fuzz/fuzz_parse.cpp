// libFuzzer target: the .node and xy parsers on arbitrary bytes (see fuzz_checks.h).
#include <cstdio>
#include <cstdlib>

#include "fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string e = dtfuzz::checkParse(data, size);
  if (!e.empty()) {
    std::fprintf(stderr, "fuzz_parse: %s\n", e.c_str());
    std::abort();
  }
  return 0;
}
