// The command line's program as a function: cli/main.cpp runs it with no hooks; the tests'
// driver (tests/hooks/delaunay2d_hooked.cpp) runs the same code with hooks of its own.
#pragma once

namespace dt::cli {

/// Points where a test makes the program wait, to send a signal or to start a second run
/// there. Negative: no wait (what the installed program always passes).
struct TestHooks {
  /// Once every output is written beside its target, before the commit: say "holding" on stderr
  /// and sleep this many seconds.
  int holdOutputsSeconds = -1;
  /// After each rename of the commit, and after the commit: say "committing N" (or
  /// "committed") on stderr and sleep this many milliseconds.
  long commitPauseMs = -1;
};

/// delaunay2d with the arguments of main; returns the exit status (or exits, for --help and a
/// usage error).
int run(int argc, char** argv, const TestHooks& hooks);

}  // namespace dt::cli
