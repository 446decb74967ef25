#include "huge_pages.h"

#include <atomic>
#include <cstdint>

#include "parallel_for.h"

#include <sys/mman.h>

namespace dt {

namespace {

// madvise(advice) on the whole pages of `page` bytes (a power of two) inside [p, p + bytes), cut
// into `threads` consecutive pieces of whole pages, one call per piece, each on its own thread:
// false if there is no whole page or the kernel refuses a piece.
bool adviseWholePages(const void* p, std::size_t bytes, std::uintptr_t page, int advice,
                      int threads = 1) {
  const std::uintptr_t a = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t lo = (a + page - 1) & ~(page - 1), hi = (a + bytes) & ~(page - 1);
  if (hi <= lo) return false;
  std::atomic<bool> ok{true};
  parallelFor(threads, (hi - lo) / page, [&](int, std::size_t from, std::size_t to) {
    if (to > from && ::madvise(reinterpret_cast<void*>(lo + from * page), (to - from) * page,
                               advice) != 0)
      ok = false;
  });
  return ok;
}

}  // namespace

void adviseHugePages(const void* p, std::size_t bytes) {
  adviseWholePages(p, bytes, std::uintptr_t{1} << 21, MADV_HUGEPAGE);
}

bool populatePages(const void* p, std::size_t bytes, int threads) {
#ifdef MADV_POPULATE_WRITE
  return adviseWholePages(p, bytes, 4096, MADV_POPULATE_WRITE, threads);
#else
  (void)p, (void)bytes, (void)threads;
  return false;
#endif
}

}  // namespace dt
