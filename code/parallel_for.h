// Internal helper of the fast kernels and their sort: one loop cut into consecutive pieces, one
// thread a piece. Plain std::thread, started per call: the callers run a few long loops.
#pragma once

#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace dt {

/// body(k, lo, hi) on `threads` consecutive pieces [lo, hi) of [0, n), piece k by thread k
/// (piece 0 by the calling thread; threads <= 1: one call on the calling thread). The pieces
/// have sizes n / threads up to one. An exception of any piece is rethrown after all joined.
template <class Body>
void parallelFor(int threads, std::size_t n, Body body) {
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
  std::vector<std::thread> pool;
  for (int k = 1; k < threads; ++k) pool.emplace_back(piece, k);
  piece(0);
  for (std::thread& th : pool) th.join();
  for (const std::exception_ptr& e : err)
    if (e) std::rethrow_exception(e);
}

}  // namespace dt
