// The window's percentiles against an independent reference: the nearest rank read off a sorted copy.
#include "io/lcm_diagnostics/window_figures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace cerebellum {
namespace {

// the p-th percentile by its definition: the smallest sample with at least p % at or below it
double by_definition(std::vector<double> samples, double p) {
  std::sort(samples.begin(), samples.end());
  for (double candidate : samples) {
    const auto at_or_below = std::count_if(samples.begin(), samples.end(), [&](double s) { return s <= candidate; });
    if (static_cast<double>(at_or_below) >= p / 100.0 * static_cast<double>(samples.size())) return candidate;
  }
  return samples.back();
}

TEST(WindowFigures, MatchTheNearestRankDefinitionOnRandomWindowsOfEverySize) {
  std::mt19937 rng(7);
  std::lognormal_distribution<double> period(std::log(0.002), 0.3);
  for (std::size_t count : {1u, 2u, 3u, 99u, 100u, 101u, 500u, 1024u}) {
    std::vector<double> samples(count);
    for (double& s : samples) s = period(rng);
    std::vector<double> work = samples;
    const WindowFigures figures = window_figures(work.data(), work.size());
    EXPECT_DOUBLE_EQ(figures.p50, by_definition(samples, 50.0)) << count;
    EXPECT_DOUBLE_EQ(figures.p99, by_definition(samples, 99.0)) << count;
    EXPECT_DOUBLE_EQ(figures.max, *std::max_element(samples.begin(), samples.end())) << count;
  }
}

TEST(WindowFigures, OneLateTickInFiveHundredShowsOnlyInTheMaximum) {
  std::vector<double> periods(500, 0.002);
  periods[137] = 0.031;  // a stall of the machine
  const WindowFigures figures = window_figures(periods.data(), periods.size());
  EXPECT_DOUBLE_EQ(figures.p50, 0.002);
  EXPECT_DOUBLE_EQ(figures.p99, 0.002);
  EXPECT_DOUBLE_EQ(figures.max, 0.031);
}

TEST(WindowFigures, AnEmptyWindowIsAllZero) {
  const WindowFigures figures = window_figures(nullptr, 0);
  EXPECT_EQ(figures.p50, 0.0);
  EXPECT_EQ(figures.max, 0.0);
}

}  // namespace
}  // namespace cerebellum
