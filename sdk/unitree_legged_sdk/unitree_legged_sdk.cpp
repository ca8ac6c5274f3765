#include "unitree_legged_sdk/unitree_legged_sdk.h"

#include <sys/mman.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace UNITREE_LEGGED_SDK {

void InitEnvironment() {
  if (::mlockall(MCL_CURRENT | MCL_FUTURE) != 0) {
    std::fprintf(stderr, "InitEnvironment: memory not locked (%s); the loop may see page faults\n",
                 std::strerror(errno));
  }
}

}  // namespace UNITREE_LEGGED_SDK
