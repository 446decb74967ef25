// The process's peak resident memory (for --stats and the benchmarks).
#pragma once

namespace dt {

/// Peak resident memory of this process so far (VmHWM of /proc/self/status), in kB; 0 where
/// /proc is not available. Counts only this program's own image (unlike ru_maxrss of a child,
/// which includes the pages its parent had before the exec).
long peakResidentKB();

}  // namespace dt
