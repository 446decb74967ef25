// Running another program without a shell: an argument vector goes to execvp as it is, so a
// path with a space, a quote, `$(...)`, `;` or a leading '-' is one argument and nothing else.
// Used by chapters/common.h (gnuplot, perf) and by the tests (tests/support.h).
//
// The call form `runProgram({"prog", ...})` spells the program as the first literal of the
// vector: scripts/check_deps.sh finds every program called this way by that pattern.
#pragma once

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
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
/// working directory, an output file that cannot be opened), -1 if fork failed.
inline int runProgram(const std::vector<std::string>& argv, const ProcessIo& io = {}) {
  if (argv.empty()) return 127;
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::cout.flush();  // or the child inherits buffered text and prints it again
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    // Between fork and exec: open, dup2, chdir (async-signal-safe) and setenv, which is safe
    // as long as no other thread of the caller is changing the environment (none does).
    auto redirect = [](const std::string& path, int fd) {
      if (path.empty()) return true;
      if (path == "&1") return dup2(1, fd) >= 0;
      const int f = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
      return f >= 0 && dup2(f, fd) >= 0;
    };
    if (!redirect(io.stdoutPath, 1) || !redirect(io.stderrPath, 2)) _exit(127);
    if (!io.cwd.empty() && chdir(io.cwd.c_str()) != 0) _exit(127);
    for (const auto& kv : io.env) setenv(kv.first.c_str(), kv.second.c_str(), 1);
    execvp(args[0], args.data());
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

}  // namespace ch
