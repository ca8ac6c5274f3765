// A run's result as one CSV row of results.csv: the cell, its axes' values, the seed, the
// outcome and the measures of RunResult, each with its unit in the column's name.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sweep/run_result.hpp"
#include "sweep/scenario.hpp"

namespace cerebellum {

// an axis's value as the file would write it (a terrain axis: the spec, not its index)
std::string axis_value(const Axis& axis, double v);

// "cell,<axis>,...,seed,outcome,robot_time_s,..." (a seed axis is the seed column)
std::string result_header(const SweepSpec& spec);
std::string result_row(const SweepSpec& spec, std::uint64_t cell, const RunResult& result);

// a row split into its fields
std::vector<std::string> csv_fields(const std::string& row);
// the column's index in the header, or -1
int column_index(const std::string& header, const std::string& column);

}  // namespace cerebellum
