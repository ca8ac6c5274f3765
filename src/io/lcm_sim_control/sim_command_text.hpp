// The text of a command to the simulation (channel sim_command): one home for its words, limits
// and format, used by the simulation to parse and by the `cerebellum push` verb to write.
//   push FX FY FZ DURATION_S   a force on the trunk (N, world frame) for DURATION_S of simulated time
//   fault WORDS...             a fault to inject or clear (the grammar of backend/fault_request.hpp)
//   fault link NAME ...        a client link's fault (io/common/link_faults.hpp)
#pragma once

#include <optional>
#include <string>

#include "backend/fault_request.hpp"
#include "backend/push_request.hpp"
#include "io/common/link_faults.hpp"

namespace cerebellum {

// a push the simulated robot may get: a hard shove, never a launch (about 6 g on the 8.5 kg body)
inline constexpr double kPushForceMaxN = 500.0;
inline constexpr double kPushDurationMaxS = 10.0;
// a command text longer than this is refused before it is read
inline constexpr std::size_t kSimCommandTextMaxBytes = 256;

struct SimCommand {
  std::optional<ForcePulse> push;        // set when the command is a valid push
  std::optional<FaultRequest> fault;     // set when the command is a valid fault
  std::optional<LinkFaultRequest> link;  // set when the command is a valid link fault
  std::string error;                     // else: what is wrong, naming the word and the accepted values
};

SimCommand parse_sim_command(const std::string& text);
// the text parse_sim_command reads back as this pulse
std::string push_command_text(const ForcePulse& pulse);
std::string fault_command_text(const FaultRequest& request);
std::string fault_command_text(const LinkFaultRequest& request);

}  // namespace cerebellum
