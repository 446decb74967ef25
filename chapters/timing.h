// Timings of the charts: a chart shows the median of k runs, and its caption cites
// k by a value key (figures/ch2/timings.txt lists the charts and their keys).
#pragma once

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace ch {

/// The median of the runs (the mean of the middle two for an even count); throws on no runs.
inline double median(std::vector<double> runs) {
  if (runs.empty()) throw std::invalid_argument("median of no runs");
  std::sort(runs.begin(), runs.end());
  const std::size_t h = runs.size() / 2;
  return runs.size() % 2 ? runs[h] : 0.5 * (runs[h - 1] + runs[h]);
}

}  // namespace ch
