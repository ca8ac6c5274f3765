#include "io/lcm_diagnostics/window_figures.hpp"

#include <algorithm>
#include <cmath>

namespace cerebellum {
namespace {

// the nearest rank of percentile p among count samples, as an index from 0
std::size_t nearest_rank_index(double p, std::size_t count) {
  const auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(count)));
  return std::clamp<std::size_t>(rank, 1, count) - 1;
}

}  // namespace

WindowFigures window_figures(double* samples, std::size_t count) {
  if (count == 0) return {};
  WindowFigures figures;
  double* const end = samples + count;
  // nth_element twice (the median, then p99 in the upper part) rather than a full sort: the loop's
  // 500 samples a second cost little either way, but this runs on a publisher thread beside the loop
  const std::size_t i50 = nearest_rank_index(50.0, count);
  std::nth_element(samples, samples + i50, end);
  figures.p50 = samples[i50];
  const std::size_t i99 = nearest_rank_index(99.0, count);
  std::nth_element(samples + i50, samples + i99, end);
  figures.p99 = samples[i99];
  figures.max = *std::max_element(samples + i99, end);
  return figures;
}

}  // namespace cerebellum
