// The simulation's ground truth as the wire type sim_truth_lcmt (lcm/sim_truth_lcmt.lcm).
#pragma once

#include "backend/simulation.hpp"
#include "sim_truth_lcmt.hpp"

namespace cerebellum {

// time_s: the simulation's clock; the message carries it in ns
sim_truth_lcmt make_sim_truth_message(const GroundTruth& truth, double time_s);

}  // namespace cerebellum
