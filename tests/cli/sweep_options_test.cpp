// The options of `cerebellum sweep`: defaults, what goes together and what does not.
#include "cli/sweep_options.hpp"

#include <gtest/gtest.h>

namespace cerebellum {
namespace {

std::string refusal(const std::vector<std::string>& args) {
  try {
    parse_sweep_options(args);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "<accepted>";
}

TEST(SweepOptions, TheOutputFolderDefaultsToTheScenariosName) {
  const SweepOptions o = parse_sweep_options({"bench/sweeps/push_sweep.yaml"});
  EXPECT_EQ(o.out, "sweep-push_sweep");
  EXPECT_EQ(o.jobs, 0);  // all cores
  EXPECT_FALSE(o.slurm.has_value());
}

TEST(SweepOptions, SlurmsOptionsAreKept) {
  const SweepOptions o =
      parse_sweep_options({"s.yaml", "--slurm", "--partition", "cpu", "--time", "30", "--tasks", "8", "--no-wait"});
  ASSERT_TRUE(o.slurm.has_value());
  EXPECT_EQ(o.slurm->partition, "cpu");
  EXPECT_EQ(o.slurm->time_limit, "30");
  EXPECT_EQ(o.slurm->tasks, 8);
  EXPECT_FALSE(o.slurm->wait);
}

TEST(SweepOptions, SlurmsOptionsWithoutSlurmAreRefused) {
  EXPECT_EQ(refusal({"s.yaml", "--partition", "cpu"}), "--partition, --time, --tasks, --sbatch and --no-wait go with --slurm");
}

TEST(SweepOptions, ASliceIsAnIndexBelowItsCount) {
  const SweepOptions o = parse_sweep_options({"s.yaml", "--slice", "2/5"});
  ASSERT_TRUE(o.slice.has_value());
  EXPECT_EQ(o.slice->first, 2u);
  EXPECT_EQ(o.slice->second, 5u);
  EXPECT_EQ(refusal({"s.yaml", "--slice", "5/5"}), "--slice: '5' is not a whole number in [0, 4]");
  EXPECT_EQ(refusal({"s.yaml", "--slice", "5"}), "--slice: '5' is not I/N");
}

TEST(SweepOptions, BadValuesAndUnknownOptionsAreRefused) {
  EXPECT_EQ(refusal({"s.yaml", "-j", "0"}), "-j: '0' is not a whole number in [1, 4096]");
  EXPECT_EQ(refusal({"s.yaml", "--jobz", "2"}), "unknown option '--jobz' (cerebellum sweep --help)");
  EXPECT_EQ(refusal({"a.yaml", "b.yaml"}), "one scenario file only; got 'a.yaml' and 'b.yaml'");
  EXPECT_EQ(refusal({}), "give the scenario file (cerebellum sweep --help)");
  EXPECT_EQ(refusal({"s.yaml", "--cell", "1", "--slurm"}), "--cell runs one cell here; not with --slurm or --slice");
  EXPECT_EQ(refusal({"s.yaml", "--status", "dir"}), "--status DIR takes no scenario file");
}

}  // namespace
}  // namespace cerebellum
