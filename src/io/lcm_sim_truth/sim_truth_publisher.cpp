#include "io/lcm_sim_truth/sim_truth_publisher.hpp"

#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "io/lcm_common/lcm_url.hpp"
#include "io/lcm_sim_truth/sim_truth_message.hpp"

namespace cerebellum {
namespace {

std::uint64_t ticks_per_message(double rate_hz, double loop_period_s) {
  if (!(rate_hz > 0.0 && rate_hz <= kSimTruthRateMaxHz)) {
    throw std::invalid_argument("sim_truth rate must be in (0, " + std::to_string(kSimTruthRateMaxHz) + "] Hz, got " +
                                std::to_string(rate_hz));
  }
  return static_cast<std::uint64_t>(std::max(1.0, std::round(1.0 / (rate_hz * loop_period_s))));
}

}  // namespace

SimTruthPublisher::SimTruthPublisher(const Simulation& simulation, const std::string& url, const SimTruthConfig& config,
                                     double loop_period_s)
    : simulation_(simulation),
      ticks_per_message_(ticks_per_message(config.rate_hz, loop_period_s)),
      lcm_(open_lcm_url(url, "sim_truth")) {
  thread_.start_publishing(samples_, [this](const Sample& sample) { publish(sample); });
}

SimTruthPublisher::~SimTruthPublisher() { thread_.stop(); }

void SimTruthPublisher::on_cycle(const CycleRecord& record) {
  if (record.tick % ticks_per_message_ == 0) {
    samples_.try_push(Sample{simulation_.ground_truth(), simulation_.time_s()});
  }
}

void SimTruthPublisher::finish() { thread_.stop(); }

void SimTruthPublisher::publish(const Sample& sample) {
  const sim_truth_lcmt message = make_sim_truth_message(sample.truth, sample.time_s);
  lcm_->publish(kSimTruthChannel, &message);
  published_.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace cerebellum
