#include "cli/client_interfaces.hpp"

#include <cmath>

namespace cerebellum {

ClientInterfaces::ClientInterfaces(Mc& mc, LinkFaultSet* link_faults, std::FILE* log) {
  const McConfig& config = mc.config();
  ControlLoop& loop = mc.loop();
  if (config.shm.enabled) {
    shm_.emplace(config.shm, config.safety, log);
    if (link_faults != nullptr) shm_->attach_link_faults(link_faults->shm);
    mc.arbiter().add_low_level_source(shm_->source());
    loop.add_substep_participant(*shm_);
  }
  if (config.motor_sdk.enabled) {
    motor_sdk_.emplace(config.motor_sdk, log);
    if (link_faults != nullptr) motor_sdk_->attach_link_faults(link_faults->motor_sdk);
    mc.arbiter().add_low_level_source(motor_sdk_->source());
    loop.add_observer(*motor_sdk_);
  }
  if (config.highlevel.enabled) {
    highlevel_.emplace(mc.client_port(HighLevelSource::CyberDog2Lcm), mc.user_gait_upload(), config.highlevel,
                       config.loop_period_s, log);
    if (link_faults != nullptr) highlevel_->attach_link_faults(link_faults->highlevel);
    loop.add_observer(*highlevel_);
    // where `cerebellum status` reads the responses, the MC's own figures once a second
    diagnostics_.emplace(config.highlevel.response_url, robot_kind_name(config.robot_kind),
                         static_cast<std::size_t>(std::lround(1.0 / config.loop_period_s)));
    loop.add_observer(*diagnostics_);
  }
  if (config.aliengo.enabled) {
    aliengo_.emplace(mc.client_port(HighLevelSource::AlienGoUdp), mc.aliengo_source().inbox(), config.aliengo, log);
    if (link_faults != nullptr) aliengo_->attach_link_faults(link_faults->aliengo);
    loop.add_observer(*aliengo_);
  }
  // state_estimator and leg_control_data: listed by both interfaces, published once for both
  if (config.motor_sdk.enabled || config.highlevel.enabled) {
    state_feedback_.emplace(config.motor_sdk.control_url, config.motor_sdk.estimator_url, config.loop_period_s,
                            motor_sdk_ ? &motor_sdk_->source() : nullptr);
    loop.add_observer(*state_feedback_);
  }
}

void ClientInterfaces::finish(std::FILE* out) {
  if (motor_sdk_) motor_sdk_->finish(out);
  if (highlevel_) highlevel_->finish(out);
  if (aliengo_) aliengo_->finish(out);
  if (state_feedback_) state_feedback_->finish();
  if (diagnostics_) diagnostics_->finish();
}

}  // namespace cerebellum
