// The text the viewer and the recorder draw over the scene (mjr_overlay: a column of titles and
// a column of values).
#pragma once

#include <string>

#include "core/high_level_command.hpp"
#include "viz/sim_snapshot.hpp"

namespace cerebellum {

struct OverlayText {
  std::string titles;  // one line per row
  std::string values;
};

// the interface's name of a mode id, or "mode <id>" for an id the MC does not run
std::string mode_name(int mode);
const char* switch_status_name(SwitchStatus status);

// time, mode, gait, switch status, estimated and true (simulator) velocity and height;
// run_state: a row such as "running 1x" or "paused" (empty: no row); keys_state: a last row, the
// viewer keyboard's command (empty: no row)
OverlayText status_overlay(const SimSnapshot& snapshot, const std::string& run_state,
                           const std::string& keys_state = "");

}  // namespace cerebellum
