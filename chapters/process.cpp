// The body of chapters/process.h's runProgram and its signal handling, compiled once.
#include "process.h"

namespace ch {

namespace detail {

// The child runProgram waits for, where a signal handler can read it; 0 for none.
volatile sig_atomic_t runningChild = 0;
constexpr int kEndingSignals[] = {SIGINT, SIGTERM, SIGHUP};
struct sigaction callersAction[32];

// SIGINT, SIGTERM or SIGHUP while a child runs: the child gets the same signal and is waited
// for (no gnuplot left running, reparented, still writing figures), then the caller's own
// action for the signal takes it (its handler, or the default: the process ends by it).
void endChildThenSelf(int sig) {
  const pid_t child = pid_t(runningChild);
  if (child > 0) {
    ::kill(child, sig);
    while (::waitpid(child, nullptr, 0) < 0 && errno == EINTR) {
    }
    runningChild = 0;
  }
  ::sigaction(sig, &callersAction[sig], nullptr);
  ::raise(sig);  // delivered when this handler returns (the signal is blocked until then)
}

}  // namespace detail

int runProgram(const std::vector<std::string>& argv, const ProcessIo& io) {
  if (argv.empty()) return 127;
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::cout.flush();  // or the child inherits buffered text and prints it again
  std::cerr.flush();
  std::fflush(nullptr);
  // The handlers go in before fork, with the signals blocked until the child's pid is known.
  sigset_t ending, old;
  sigemptyset(&ending);
  for (int sig : detail::kEndingSignals) sigaddset(&ending, sig);
  sigprocmask(SIG_BLOCK, &ending, &old);
  bool forwarded[32] = {};
  for (int sig : detail::kEndingSignals) {
    struct sigaction mine;
    std::memset(&mine, 0, sizeof mine);
    mine.sa_handler = detail::endChildThenSelf;
    sigemptyset(&mine.sa_mask);
    if (sigaction(sig, nullptr, &detail::callersAction[sig]) == 0 &&
        detail::callersAction[sig].sa_handler != SIG_IGN)
      forwarded[sig] = sigaction(sig, &mine, nullptr) == 0;
  }
  auto restore = [&] {
    sigprocmask(SIG_BLOCK, &ending, nullptr);  // a signal now is the caller's again
    for (int sig : detail::kEndingSignals)
      if (forwarded[sig]) sigaction(sig, &detail::callersAction[sig], nullptr);
    detail::runningChild = 0;
    sigprocmask(SIG_SETMASK, &old, nullptr);
  };
  const pid_t pid = fork();
  if (pid < 0) {
    restore();
    return -1;
  }
  if (pid == 0) {
    // The child starts with the caller's actions and mask (exec keeps the mask).
    for (int sig : detail::kEndingSignals)
      if (forwarded[sig]) sigaction(sig, &detail::callersAction[sig], nullptr);
    sigprocmask(SIG_SETMASK, &old, nullptr);
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
  detail::runningChild = pid;
  sigprocmask(SIG_SETMASK, &old, nullptr);  // a signal from here on reaches the child
  // Waited for without reaping it first: while the handler may still signal the pid, it stays
  // this child's (never a new process's that took the number).
  siginfo_t info;
  while (waitid(P_PID, id_t(pid), &info, WEXITED | WNOWAIT) < 0) {
    if (errno != EINTR) {
      restore();  // reaped by the handler: the caller's handler returned, not ended the process
      return -1;
    }
  }
  restore();
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

}  // namespace ch
