/* maps the shared-memory object named on the command line with lowlevel.h, as a client does */
#include "lowlevel/lowlevel.h"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  lowlevel_map_shm(argv[1], 1024);
  return 0;
}
