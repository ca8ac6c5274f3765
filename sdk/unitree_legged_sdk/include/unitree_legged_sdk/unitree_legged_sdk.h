// The AlienGo high-level SDK API, written from docs/aliengo-udp.md so that programs written for
// the vendor's SDK compile and run unchanged against cerebellum (`cerebellum sim`).
#pragma once

#include "unitree_legged_sdk/comm.h"
#include "unitree_legged_sdk/loop.h"
#include "unitree_legged_sdk/safety.h"
#include "unitree_legged_sdk/udp.h"

namespace UNITREE_LEGGED_SDK {

// prepares the process for a 2 ms loop: locks its memory (no page faults in the loop); warns on
// stderr when the system does not allow it and carries on
void InitEnvironment();

}  // namespace UNITREE_LEGGED_SDK
