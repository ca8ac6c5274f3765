// The human form of user gait parameters (seed section 2.2.2: type = "usergait", body_vel_des,
// body_pos_des, landing_pos_des, step_height, weight, use_mpc_traj, mu, landing_gain, gait_id,
// duration) converted to the form the MC takes on user_gait_file (robot_control_cmd fields per
// step), field for field as the seed's example client converts it (section 2.4.3).
#pragma once

#include <string>
#include <string_view>

namespace cerebellum {

struct UserGaitConversion {
  std::string text;   // "# Gait Params" and one [[step]] of command fields per step
  std::string error;  // why the human form cannot be converted (step, key, expected)
};

// true when the text is already in the uploaded form (its steps have a mode key)
bool is_converted_gait_parameters(std::string_view text);
UserGaitConversion convert_gait_parameters(std::string_view human_text);

}  // namespace cerebellum
