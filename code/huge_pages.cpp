#include "huge_pages.h"

#include <atomic>
#include <cstdint>

#include "parallel_for.h"

#include <sys/mman.h>

namespace dt {

namespace {

// madvise(advice) on the whole pages of `page` bytes (a power of two) inside [p, p + bytes):
// false if there is none or the kernel refuses.
bool adviseWholePages(const void* p, std::size_t bytes, std::uintptr_t page, int advice) {
  const std::uintptr_t a = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t lo = (a + page - 1) & ~(page - 1), hi = (a + bytes) & ~(page - 1);
  return hi > lo && ::madvise(reinterpret_cast<void*>(lo), hi - lo, advice) == 0;
}

}  // namespace

void adviseHugePages(const void* p, std::size_t bytes) {
  adviseWholePages(p, bytes, std::uintptr_t{1} << 21, MADV_HUGEPAGE);
}

bool populatePages(const void* p, std::size_t bytes, int threads) {
#ifdef MADV_POPULATE_WRITE
  constexpr std::size_t kPage = 4096;
  const std::uintptr_t a = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t lo = (a + kPage - 1) & ~std::uintptr_t(kPage - 1);
  const std::size_t pages = (a + bytes) / kPage > lo / kPage ? (a + bytes) / kPage - lo / kPage : 0;
  std::atomic<bool> ok{true};
  parallelFor(threads, pages, [&](int, std::size_t from, std::size_t to) {
    if (to > from && !adviseWholePages(reinterpret_cast<const void*>(lo + from * kPage),
                                       (to - from) * kPage, kPage, MADV_POPULATE_WRITE))
      ok = false;
  });
  return ok && pages > 0;
#else
  (void)p, (void)bytes, (void)threads;
  return false;
#endif
}

}  // namespace dt
