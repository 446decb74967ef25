// The body of chapters/timing.h's median, compiled once.
#include "timing.h"

namespace ch {

double median(std::vector<double> runs) {
  if (runs.empty()) throw std::invalid_argument("median of no runs");
  std::sort(runs.begin(), runs.end());
  const std::size_t h = runs.size() / 2;
  return runs.size() % 2 ? runs[h] : 0.5 * (runs[h - 1] + runs[h]);
}

}  // namespace ch
