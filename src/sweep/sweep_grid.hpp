// The grid of a sweep: every combination of its axes' values, numbered 0..size-1 with the last
// axis varying fastest, and the scenario of one cell (the base with the cell's values applied).
#pragma once

#include <cstdint>
#include <vector>

#include "sweep/scenario.hpp"

namespace cerebellum {

// grids larger than this are not counted further (the product saturates here)
inline constexpr std::uint64_t kGridSizeCap = std::uint64_t{1} << 40;

// the number of cells (1 without axes), at most kGridSizeCap
std::uint64_t grid_size(const SweepSpec& spec);

// each axis's value at the cell (one per axis, in the axes' order); index < grid_size(spec)
std::vector<double> cell_values(const SweepSpec& spec, std::uint64_t index);

// the base scenario with the cell's values: seed -> seed; gait -> every walking command's gait;
// push_* -> that field of every push
Scenario cell_scenario(const SweepSpec& spec, std::uint64_t index);

}  // namespace cerebellum
