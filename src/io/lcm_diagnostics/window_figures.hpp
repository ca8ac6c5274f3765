// p50, p99 and the largest of one window's samples (the loop's period, the state's age), for the
// MC's once-a-second diagnostics: nearest-rank percentiles, exact for the window's own samples.
#pragma once

#include <array>
#include <cstddef>

namespace cerebellum {

struct WindowFigures {
  double p50 = 0.0;
  double p99 = 0.0;
  double max = 0.0;
};

// reorders samples[0, count); all zero for an empty window. Nearest rank: the p-th percentile is
// the smallest sample with at least p % of the samples at or below it
WindowFigures window_figures(double* samples, std::size_t count);

}  // namespace cerebellum
