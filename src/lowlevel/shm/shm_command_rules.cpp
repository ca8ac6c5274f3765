#include "lowlevel/shm/shm_command_rules.hpp"

#include "safety/command_finite.hpp"

namespace cerebellum {
namespace {

ShmCommandCheck fault_at(ShmCommandFault fault, std::size_t joint, ShmCommandField field, double value) {
  ShmCommandCheck check;
  check.fault = fault;
  check.joint = joint;
  check.field = field;
  check.value = value;
  return check;
}

}  // namespace

ShmCommandCheck check_shm_command(const JointCommand& command, const CommandLimits& limits) {
  for (std::size_t i = 0; i < kNumJoints; ++i) {
    if (const auto field = non_finite_field(command, i)) {
      return fault_at(ShmCommandFault::NonFinite, i, static_cast<ShmCommandField>(*field),
                      command_value(command, i, *field));
    }
    if (command.kp[i] < 0.0 || command.kp[i] > limits.kp_max) {
      return fault_at(ShmCommandFault::GainOutOfRange, i, ShmCommandField::Kp, command.kp[i]);
    }
    if (command.kd[i] < 0.0 || command.kd[i] > limits.kd_max) {
      return fault_at(ShmCommandFault::GainOutOfRange, i, ShmCommandField::Kd, command.kd[i]);
    }
  }
  return {};
}

const char* shm_command_field_name(ShmCommandField field) {
  switch (field) {
    case ShmCommandField::PDes: return "p_des";
    case ShmCommandField::VDes: return "v_des";
    case ShmCommandField::Kp: return "kp";
    case ShmCommandField::Kd: return "kd";
    case ShmCommandField::TFf: return "t_ff";
  }
  return "?";
}

}  // namespace cerebellum
