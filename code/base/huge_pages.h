// How the large arrays of the fast kernels and of the Hilbert sort get their memory (an internal
// helper): the sort's short-lived arrays in 2 MB pages where the system allows it, the kernel's
// triangle arrays in small pages mapped in one call (fast_core.h's Store says why).
#pragma once

#include <cstddef>
#include <vector>

namespace dt {

/// Asks the kernel to back [p, p + bytes) with 2 MB pages where it can (transparent huge pages
/// in "madvise" mode, Debian's default): the sort's arrays of 10^6 points span tens of MB, and
/// with 4 KB pages their first touch costs one page fault per 4 KB (a third of a sort's time in
/// a fresh process). A hint only: nothing changes where it is refused.
void adviseHugePages(const void* p, std::size_t bytes);

/// Asks the kernel to map the whole 4 KB pages inside [p, p + bytes) now, in one call
/// (MADV_POPULATE_WRITE, Linux 5.14), rather than by one page fault per page at first touch:
/// the same zeroed pages, without a trap into the kernel for each. A hint only: false where the
/// kernel refuses it (an older one), and nothing changes. threads > 1: the pages are cut into
/// that many consecutive pieces, one call per piece, each on its own thread (the kernel clears a
/// page on the thread that asks for it).
bool populatePages(const void* p, std::size_t bytes, int threads = 1);

/// n copies of v in a vector whose storage was given the 2 MB hint (adviseHugePages) before
/// its first touch.
template <class T>
std::vector<T> hugeVector(std::size_t n, const T& v = T()) {
  std::vector<T> a;
  a.reserve(n);
  adviseHugePages(a.data(), n * sizeof(T));
  a.assign(n, v);
  return a;
}

}  // namespace dt
