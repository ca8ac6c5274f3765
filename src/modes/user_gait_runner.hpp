// Gait 110 of mode 11: runs the uploaded user gait once on the walking controller. The
// definition's contact schedule is played from the first section; the parameter steps follow one
// another in time (body velocity, or where a step gives none its position offset, integrated into
// position; pose, each swing leg's landing point and height); when the total time is done the
// robot stands on the MPC and waits. The progress bar is the elapsed share of the total time.
#pragma once

#include <memory>

#include "modes/locomotion_gait.hpp"
#include "modes/user_gait.hpp"
#include "modes/walking_gaits.hpp"

namespace cerebellum {

class UserGaitRunner final : public LocomotionGait {
 public:
  UserGaitRunner(WalkingGaits& walking, const UserGaitSlot& slot);

  // refused while nothing is uploaded
  const char* check(const HighLevelCommand& command) const override;
  void start(const RobotState& state, const LocomotionCommand& command) override;
  void update(const LocomotionCommand&) override {}  // a running gait is not steered by clients
  void run(const RobotState& state, JointCommand& command) override;
  ContactPlan contact_plan() const override { return walking_.contact_plan(); }
  void stop() override;
  int progress_percent() const override;
  bool damping_protection() const override { return walking_.failed(); }

  // the next start() runs this program instead of the uploaded one (a motion's own gait)
  void use_next(std::shared_ptr<const UserGaitProgram> program) { next_ = std::move(program); }
  // the gait being run (none before start)
  const UserGaitProgram* program() const { return program_.get(); }
  bool finished() const { return finished_; }

 private:
  void steer_to_step(std::size_t index);

  WalkingGaits& walking_;
  const UserGaitSlot& slot_;
  std::shared_ptr<const UserGaitProgram> program_;
  std::shared_ptr<const UserGaitProgram> next_;
  double start_s_ = 0.0;
  double total_s_ = 0.0;  // the program's length, summed once at the start, not every tick
  double elapsed_s_ = 0.0;
  std::size_t step_ = 0;
  double step_end_s_ = 0.0;
  bool finished_ = false;
};

}  // namespace cerebellum
