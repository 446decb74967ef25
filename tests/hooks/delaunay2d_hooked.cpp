// delaunay2d for the tests that must catch it at a given moment (tests/test_cli.cpp):
//   delaunay2d_hooked [--hold-outputs SECONDS] [--commit-pause-ms MS] ARGS...
// takes its hooks from its leading options and runs the program with ARGS, as main would.
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <vector>

#include "delaunay2d.h"

int main(int argc, char** argv) {
  dt::cli::TestHooks hooks;
  int i = 1;
  auto is = [&](const char* name) { return std::strcmp(argv[i], name) == 0; };
  while (i + 1 < argc && (is("--hold-outputs") || is("--commit-pause-ms"))) {
    char* end = nullptr;
    const long v = std::strtol(argv[i + 1], &end, 10);
    if (end == argv[i + 1] || *end != '\0' || v < 0) {
      std::cerr << "delaunay2d_hooked: " << argv[i] << " takes a count >= 0, not '" << argv[i + 1] << "'\n";
      return 2;
    }
    if (is("--hold-outputs")) hooks.holdOutputsSeconds = int(v);
    else hooks.commitPauseMs = v;
    i += 2;
  }
  // The program sees its own name and the arguments after the hooks.
  std::vector<char*> args{argv[0]};
  for (; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  return dt::cli::run(int(args.size()) - 1, args.data(), hooks);
}
