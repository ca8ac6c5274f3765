// From the uploaded user gait files to the MC's own UserGaitProgram (modes/user_gait.hpp), with
// the checks that make a gait unsafe to run. The parameters arrive as robot_control_cmd fields
// (the example client's conversion, shared/reference/cyberdog2-highlevel.md section 6):
//   vel_des = body velocity (vx, vy, yaw rate); rpy_des = roll, pitch, yaw; pos_des[0:2] = how far
//   the body moves in x, y where vel_des gives no velocity; pos_des[2] = height (0: the default);
//   foot_pose[0:2] FR landing x, y; [2:4] FL; [4:6] RR; ctrl_point[0:2] RL;
//   ctrl_point[2] = mu; step_height[0] = FR mm + 1000 * FL mm, [1] = RR + 1000 * RL;
//   contact % 100 = landing_gain * 10; duration in ms. acc_des (the WBC weights) and value bit 0
//   (use_mpc_traj) are accepted and not used: this MC has no WBC (kUnusedGaitParameters).
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "motions/user_gait_file.hpp"
#include "modes/user_gait.hpp"

namespace cerebellum {

// the longest all-feet-in-the-air stretch a definition may have: the pronk's flight (gait table)
int max_flight_segments();
// a definition or parameters file runs at most this long
inline constexpr double kMaxUserGaitS = 120.0;

// empty when the definition can be run, else why not (section, what, limit)
std::string definition_problem(const UserGaitDefinition& definition);
// empty when the parameters can be run, else why not (step, key, expected vs found)
std::string parameters_problem(const UserGaitParameters& parameters);
// the one of the two that applies to a parsed file
std::string user_gait_file_problem(const UserGaitFile& file);

// what the uploaded parameters hold that this MC does not use, and why (the upload's log line says it)
inline constexpr std::string_view kUnusedGaitParameters =
    "acc_des (WBC weights) and value bit 0 (use_mpc_traj) not used: no WBC here, the MPC drives the trunk "
    "with fixed weights along the steps' integrated velocity";

// the step a parameter block decodes to (values clamped as docs/highlevel.md lists)
UserGaitStep decode_user_gait_step(const HighLevelCommand& step);
// both parts, checked, into a program
std::shared_ptr<const UserGaitProgram> build_user_gait_program(const UserGaitDefinition& definition,
                                                               const UserGaitParameters& parameters);

}  // namespace cerebellum
