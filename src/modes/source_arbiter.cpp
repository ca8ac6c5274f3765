#include "modes/source_arbiter.hpp"

namespace cerebellum {

SourceArbiter::SourceArbiter(OwnBehaviour& own) : own_(own) { sources_.reserve(4); }

void SourceArbiter::add_low_level_source(LowLevelSource& source) { sources_.push_back(&source); }

void SourceArbiter::compute(const RobotState& state, JointCommand& command) {
  for (LowLevelSource* source : sources_) {
    if (source == latched_ || !source->wants_control()) continue;
    if (latched_ == nullptr && own_.allows_low_level_latch()) {
      latched_ = source;
      own_.on_handover();
      source->on_latched(state);
    } else {
      ++refusals_;
      source->on_refused(latched_ != nullptr ? latched_->name() : "the MC (not in Off or PureDamper)");
    }
  }
  if (latched_ != nullptr) {
    latched_->compute(state, command);
    own_.observe_while_held(state, latched_->name());
  } else {
    own_.compute(state, command);
  }
}

ContactPlan SourceArbiter::contact_plan() const {
  return latched_ != nullptr ? latched_->contact_plan() : own_.contact_plan();
}

}  // namespace cerebellum
