// Named motions of mode 62: a list of timed steps, each a command of another mode (pose control,
// QP stand, locomotion, recovery stand). The steps are data (motions/ reads them from files); the
// MotionMode runs them.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/high_level_command.hpp"
#include "modes/user_gait.hpp"

namespace cerebellum {

// motion ids: the MC's own motions, then the slots users fill with files of their own
inline constexpr int kFirstBuiltInMotionId = 1;
inline constexpr int kLastBuiltInMotionId = 79;
inline constexpr int kFirstUserMotionId = 80;
inline constexpr int kLastUserMotionId = 100;

struct Motion {
  int id = 0;
  std::string name;
  std::string origin;                   // the file it was read from, for messages
  std::vector<HighLevelCommand> steps;  // each runs for its duration (ms), then the next starts
  // a motion's own user gait (definition and parameters files, resolved paths), run by its steps
  // of mode 11 gait 110 instead of the uploaded one; the program is attached by the MC at start
  std::string user_gait_definition;
  std::string user_gait_parameters;
  std::shared_ptr<const UserGaitProgram> user_gait;

  // the planned length: the sum of the steps' durations
  double duration_s() const {
    double total_ms = 0.0;
    for (const HighLevelCommand& step : steps) total_ms += step.duration;
    return total_ms * 1e-3;
  }
};

// the motions the MC knows, by id
class MotionLibrary {
 public:
  // false (and nothing changes) when a motion with this id is already there
  bool add(Motion motion);
  // nullptr for an id no motion has
  const Motion* find(int id) const;
  const std::vector<Motion>& motions() const { return motions_; }
  std::vector<Motion>& motions() { return motions_; }
  // "1 2 3 ..." for messages
  std::string id_list() const;

 private:
  std::vector<Motion> motions_;
};

}  // namespace cerebellum
