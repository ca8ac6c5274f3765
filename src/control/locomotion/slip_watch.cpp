#include "control/locomotion/slip_watch.hpp"

#include <cmath>
#include <stdexcept>

namespace cerebellum {

SlipWatch::SlipWatch(const SlipWatchConfig& config) : config_(config) {
  if (!(config.window_start_phase >= 0.0 && config.window_start_phase < config.window_end_phase &&
        config.window_end_phase <= 1.0)) {
    throw std::invalid_argument("slip watch: the observed window must lie within the stance, start before end");
  }
  if (!(config.share_per_stance > 0.0 && config.share_per_stance <= 1.0)) {
    throw std::invalid_argument("slip watch: share_per_stance must be in (0, 1]");
  }
  if (!(config.leave_share < config.enter_share)) {
    throw std::invalid_argument("slip watch: leave_share must lie below enter_share");
  }
}

void SlipWatch::observe(std::size_t leg, bool in_stance, double stance_phase, double foot_speed_m_s) {
  if (!in_stance) {
    if (was_stance_[leg]) end_stance(leg);
    was_stance_[leg] = false;
    return;
  }
  was_stance_[leg] = true;
  // a non-finite speed (an estimate gone bad) says nothing about the ground
  if (stance_phase >= config_.window_start_phase && stance_phase <= config_.window_end_phase &&
      std::isfinite(foot_speed_m_s)) {
    speed_sum_m_s_[leg] += foot_speed_m_s;
    ++window_ticks_[leg];
  }
}

void SlipWatch::end_stance(std::size_t leg) {
  if (window_ticks_[leg] >= config_.min_window_ticks) {
    const bool slipped = speed_sum_m_s_[leg] / window_ticks_[leg] > config_.slip_speed_m_s;
    ++telemetry_.stances_observed;
    if (slipped) ++telemetry_.stances_slipped;
    share_ += config_.share_per_stance * ((slipped ? 1.0 : 0.0) - share_);
    if (!slippery_ && share_ > config_.enter_share) {
      slippery_ = true;
      ++telemetry_.slippery_entries;
    } else if (slippery_ && share_ < config_.leave_share) {
      slippery_ = false;
    }
  }
  speed_sum_m_s_[leg] = 0.0;
  window_ticks_[leg] = 0;
}

}  // namespace cerebellum
