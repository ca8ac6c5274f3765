// main() of a benchmark that runs one real-time scenario for --seconds=S of wall time, once,
// and reports through Google Benchmark (its own flags still work).
#pragma once

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace cerebellum {

template <typename Scenario>
int run_timed_benchmark(int argc, char** argv, const char* name, double default_seconds, Scenario scenario) {
  double seconds = default_seconds;
  std::vector<char*> rest;
  const std::string option = "--seconds=";
  for (int i = 0; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind(option, 0) == 0) {
      seconds = std::stod(arg.substr(option.size()));
    } else {
      rest.push_back(argv[i]);
    }
  }
  int rest_argc = static_cast<int>(rest.size());
  benchmark::RegisterBenchmark(name, [seconds, scenario](benchmark::State& state) { scenario(state, seconds); })
      ->Iterations(1)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  benchmark::Initialize(&rest_argc, rest.data());
  if (benchmark::ReportUnrecognizedArguments(rest_argc, rest.data())) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace cerebellum
