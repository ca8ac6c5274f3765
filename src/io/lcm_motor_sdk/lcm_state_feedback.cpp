#include "io/lcm_motor_sdk/lcm_state_feedback.hpp"

#include <lcm/lcm-cpp.hpp>

#include <algorithm>
#include <cmath>

#include "io/lcm_common/lcm_url.hpp"
#include "io/lcm_motor_sdk/robot_state_messages.hpp"

namespace cerebellum {
namespace {

constexpr const char* kLegControlDataChannel = "leg_control_data";
constexpr const char* kInterfaceName = "state feedback";

}  // namespace

LcmStateFeedback::LcmStateFeedback(const std::string& leg_control_url, const std::string& estimator_url,
                                   double loop_period_s, const MotorSdkSource* motor_sdk)
    : leg_control_lcm_(open_lcm_url(leg_control_url, kInterfaceName)),
      estimator_lcm_(open_lcm_url(estimator_url, kInterfaceName)),
      ticks_per_message_(static_cast<std::uint64_t>(std::max(1.0, std::round(kStateFeedbackPeriodS / loop_period_s)))),
      motor_sdk_(motor_sdk) {
  thread_.start_publishing(feedback_, [this](const Feedback& feedback) { publish(feedback); });
}

LcmStateFeedback::~LcmStateFeedback() { thread_.stop(); }

void LcmStateFeedback::on_cycle(const CycleRecord& record) {
  const bool motor_mode = motor_sdk_ != nullptr && motor_sdk_->status().motor_mode;
  if (motor_mode || record.tick % ticks_per_message_ == 0) feedback_.try_push(Feedback{record.state, record.command});
}

void LcmStateFeedback::finish() { thread_.stop(); }

void LcmStateFeedback::publish(const Feedback& feedback) {
  const leg_control_data_lcmt legs = make_leg_control_data(feedback.state, feedback.command);
  leg_control_lcm_->publish(kLegControlDataChannel, &legs);
  const state_estimator_lcmt trunk = make_state_estimator(feedback.state);
  estimator_lcm_->publish(kStateEstimatorChannel, &trunk);
  published_.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace cerebellum
