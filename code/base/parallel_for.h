// Internal helper of the fast kernels and their sort: one loop cut into consecutive pieces, one
// thread a piece. Plain std::thread, started per call: the callers run a few long loops.
#pragma once

#include <cstddef>
#include <exception>
#include <functional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace dt {

/// How parallelFor starts a thread: std::thread by default. A test passes its own to make the
/// k-th start fail as the system does when it runs out of threads or memory.
struct ThreadStarter {
  virtual ~ThreadStarter() = default;
  virtual std::thread start(std::function<void()> run) { return std::thread(std::move(run)); }
};

/// Thrown when a thread cannot be started: "cannot start N threads: <the system's reason>".
struct ThreadStartError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// body(k, lo, hi) on `threads` consecutive pieces [lo, hi) of [0, n), piece k by thread k
/// (piece 0 by the calling thread; threads <= 1: one call on the calling thread). The pieces
/// have sizes n / threads up to one. An exception of any piece is rethrown after all joined.
/// If a thread cannot be started, the pieces of those that did start are still run and joined
/// (none is left running), and ThreadStartError is thrown instead of running the rest.
template <class Body>
void parallelFor(int threads, std::size_t n, Body body, ThreadStarter* starter = nullptr) {
  if (threads <= 1) {
    body(0, std::size_t(0), n);
    return;
  }
  std::vector<std::exception_ptr> err(static_cast<std::size_t>(threads));
  auto piece = [&](int k) {
    try {
      body(k, n * std::size_t(k) / std::size_t(threads), n * std::size_t(k + 1) / std::size_t(threads));
    } catch (...) {
      err[std::size_t(k)] = std::current_exception();
    }
  };
  ThreadStarter plain;
  ThreadStarter& start = starter != nullptr ? *starter : plain;
  std::vector<std::thread> pool;
  std::string failed;
  try {
    pool.reserve(std::size_t(threads - 1));
    for (int k = 1; k < threads; ++k) pool.push_back(start.start([&piece, k] { piece(k); }));
  } catch (const std::system_error& e) {
    failed = e.code().message();
  } catch (const std::exception& e) {  // bad_alloc: no memory for a stack
    failed = e.what();
  }
  // A std::thread destroyed while joinable ends the process: every started one is joined,
  // after the calling thread's piece (the started pieces may wait for it) if all started.
  if (failed.empty()) piece(0);
  for (std::thread& th : pool) th.join();
  if (!failed.empty())
    throw ThreadStartError("cannot start " + std::to_string(threads) + " threads: " + failed);
  for (const std::exception_ptr& e : err)
    if (e) std::rethrow_exception(e);
}

}  // namespace dt
