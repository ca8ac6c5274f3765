// Publishes the simulation's ground truth on channel `sim_truth` for tools and users' tests. The
// MC never reads it: the simulation, not the controller, is its source. The loop thread copies the
// truth into a ring at the configured rate of simulated time; this adapter's thread publishes.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

#include "backend/simulation.hpp"
#include "core/spsc_ring.hpp"
#include "cycle/cycle_observer.hpp"
#include "io/common/adapter_thread.hpp"
#include "io/lcm_sim_truth/sim_truth_config.hpp"

namespace lcm {
class LCM;
}  // namespace lcm

namespace cerebellum {

inline constexpr const char* kSimTruthChannel = "sim_truth";

class SimTruthPublisher final : public CycleObserver {
 public:
  // url: where to publish (the odometry URL); throws std::runtime_error naming a url LCM cannot
  // open, std::invalid_argument for a rate outside (0, kSimTruthRateMaxHz]
  SimTruthPublisher(const Simulation& simulation, const std::string& url, const SimTruthConfig& config,
                    double loop_period_s);
  ~SimTruthPublisher() override;
  SimTruthPublisher(const SimTruthPublisher&) = delete;
  SimTruthPublisher& operator=(const SimTruthPublisher&) = delete;

  // loop thread (the thread that steps the simulation): copies the truth when this tick is due
  void on_cycle(const CycleRecord& record) override;

  // stops the thread after publishing what is queued
  void finish();
  std::uint64_t published() const { return published_.load(std::memory_order_relaxed); }
  std::uint64_t dropped() const { return samples_.dropped(); }

 private:
  struct Sample {
    GroundTruth truth;
    double time_s = 0.0;
  };

  void publish(const Sample& sample);

  const Simulation& simulation_;
  std::uint64_t ticks_per_message_;  // before lcm_: a bad rate is refused before a socket opens
  std::unique_ptr<lcm::LCM> lcm_;
  SpscRing<Sample, 64> samples_;
  std::atomic<std::uint64_t> published_{0};
  // last member: started once everything above is built, stopped first
  AdapterThread thread_;
};

}  // namespace cerebellum
