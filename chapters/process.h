// Running another program without a shell: an argument vector goes to execvp as it is, so a
// path with a space, a quote, `$(...)`, `;` or a leading '-' is one argument and nothing else.
// Used by chapters/common.h (gnuplot, perf) and by the tests (tests/support.h).
//
// The call form `runProgram({"prog", ...})` spells the program as the first literal of the
// vector: scripts/check_deps.sh finds every program called this way by that pattern.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <cstdio>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace ch {

/// Where a child runs and where its output goes; empty strings leave the parent's.
struct ProcessIo {
  std::string cwd;         ///< working directory of the child
  std::string stdoutPath;  ///< stdout to this file (created or truncated); "/dev/null" silences
  std::string stderrPath;  ///< stderr likewise; "&1" sends it where stdout goes
  /// Environment variables set in the child only (name, value), values passed as they are.
  std::vector<std::pair<std::string, std::string>> env;
};

/// Runs `argv` (argv[0] looked up in PATH) and waits for it. Returns its exit status, 128 + the
/// signal number if a signal ended it, 127 if it could not be started (not installed, a bad
/// working directory, an output file that cannot be opened), -1 if fork failed. SIGINT, SIGTERM
/// or SIGHUP meanwhile (unless ignored) is passed on to the child, which is waited for before
/// the signal takes its usual effect on the caller.
int runProgram(const std::vector<std::string>& argv, const ProcessIo& io = {});

}  // namespace ch
