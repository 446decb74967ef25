#include "huge_pages.h"

#include <cstdint>

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

bool populatePages(const void* p, std::size_t bytes) {
#ifdef MADV_POPULATE_WRITE
  return adviseWholePages(p, bytes, 4096, MADV_POPULATE_WRITE);
#else
  (void)p, (void)bytes;
  return false;
#endif
}

}  // namespace dt
