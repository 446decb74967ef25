// Timings of the charts: a chart shows the median of k runs, and its caption cites
// k by a value key (figures/ch2/timings.txt lists the charts and their keys).
#pragma once

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace ch {

/// The median of the runs (the mean of the middle two for an even count); throws on no runs.
double median(std::vector<double> runs);

}  // namespace ch
