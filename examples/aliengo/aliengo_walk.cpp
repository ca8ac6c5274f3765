// The AlienGo SDK's walk example timeline (docs/aliengo-udp.md), written for cerebellum's
// unitree_legged_sdk: a 2 ms loop that streams HighCmd to the robot's sport controller and reads
// HighState back. Usage: aliengo_walk [ROBOT_IP (default 127.0.0.1)]
// Against the vendor's address: run `cerebellum sim` with config/robot-network.yaml and
// aliengo_walk 192.168.123.220 (inside a network namespace that has that address, see README).
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <functional>

#include "unitree_legged_sdk/unitree_legged_sdk.h"

using namespace UNITREE_LEGGED_SDK;

class Custom {
 public:
  explicit Custom(const char* robot_ip)
      : safe(LeggedType::Aliengo), udp(8081, robot_ip, 8082, sizeof(HighCmd), sizeof(HighState)) {
    udp.InitCmdData(cmd);
  }
  void UDPRecv() { udp.Recv(); }
  void UDPSend() { udp.Send(); }
  void RobotControl();

  Safety safe;
  UDP udp;
  HighCmd cmd = {};
  HighState state = {};
  int motiontime = 0;  // ms
  float dt = 0.002f;   // s
  std::atomic<bool> done{false};
};

void Custom::RobotControl() {
  motiontime += 2;
  udp.GetRecv(state);
  if (motiontime % 1000 == 0) {
    std::printf("t=%5.1f s  mode %d  position (%+.2f, %+.2f)  rpy (%+.2f, %+.2f, %+.2f)  height %.3f\n",
                motiontime / 1000.0, state.mode, state.position[0], state.position[1], state.imu.rpy[0],
                state.imu.rpy[1], state.imu.rpy[2], state.position[2]);
    std::fflush(stdout);
  }

  // every field back to its default; the windows below set what they need
  cmd.mode = 0;
  cmd.gaitType = 0;
  cmd.speedLevel = 0;
  cmd.dFootRaiseHeight = 0;
  cmd.dBodyHeight = 0;
  cmd.position[0] = 0;
  cmd.position[1] = 0;
  cmd.rpy[0] = 0;
  cmd.rpy[1] = 0;
  cmd.rpy[2] = 0;
  cmd.velocity[0] = 0.0f;
  cmd.velocity[1] = 0.0f;
  cmd.yawSpeed = 0.0f;

  const int t = motiontime;
  if (t > 1000 && t < 2000) {
    cmd.mode = 1;
    cmd.rpy[0] = 0.7f;
  } else if (t >= 2000 && t < 3000) {
    cmd.mode = 1;
    cmd.rpy[0] = 0.0f;
  } else if (t >= 3000 && t < 4000) {
    cmd.mode = 1;
    cmd.rpy[1] = 0.4f;
  } else if (t >= 5000 && t < 6000) {
    cmd.mode = 1;
    cmd.rpy[2] = 0.5f;
  } else if (t >= 8000 && t < 9000) {
    cmd.mode = 1;
    cmd.dBodyHeight = 0.05f;
  } else if (t >= 9000 && t < 10000) {
    cmd.mode = 1;
    cmd.dBodyHeight = -0.15f;
  } else if (t >= 11000 && t < 13000) {
    cmd.mode = 2;
    cmd.velocity[0] = 0.2f;
    cmd.yawSpeed = 0.3f;
  } else if (t >= 13000 && t < 15000) {
    cmd.mode = 2;
    cmd.velocity[0] = -0.2f;
    cmd.yawSpeed = -0.1f;
    cmd.dFootRaiseHeight = 0.1f;
  } else if (t >= 15000 && t < 17000) {
    cmd.mode = 0;
  } else if (t >= 17000 && t < 23000) {
    cmd.mode = 3;
    cmd.position[0] = 1.0f;
    cmd.position[1] = 0.0f;
    cmd.rpy[2] = 0.0f;
    cmd.dBodyHeight = -0.05f;
  } else if (t >= 25000 && t < 32000) {
    cmd.mode = 2;
    cmd.gaitType = 2;
    cmd.velocity[0] = 0.1f;
  } else if (t >= 32000 && t < 40000) {
    cmd.mode = 2;
    cmd.gaitType = 2;
    cmd.velocity[0] = -0.1f;
  } else if (t >= 40000 && t < 42000) {
    cmd.mode = 1;
  } else if (t >= 42000 && t < 44000) {
    cmd.mode = 5;
  } else if (t >= 44000 && t < 46000) {
    cmd.mode = 6;
  } else if (t >= 46000 && t < 48000) {
    cmd.mode = 5;
  } else if (t >= 48000 && t < 51000) {
    cmd.mode = 7;
  } else if (t >= 51000 && t < 53000) {
    cmd.mode = 5;
  } else if (t >= 53000 && t < 55000) {
    cmd.mode = 6;
  } else if (t >= 55000 && t < 57000) {
    cmd.mode = 1;
  } else if (t >= 57000 && t < 65000) {
    cmd.mode = 3;
    cmd.position[0] = 0.0f;
    cmd.position[1] = 0.0f;
  } else if (t >= 65000) {
    cmd.mode = 0;
    done = t >= 66000;
  }
  udp.SetSend(cmd);
}

int main(int argc, char** argv) {
  const char* robot_ip = argc > 1 ? argv[1] : "127.0.0.1";
  std::printf("aliengo_walk: HighCmd to %s:8082 every 2 ms for 66 s\n", robot_ip);
  InitEnvironment();
  Custom custom(robot_ip);
  LoopFunc loop_control("control_loop", custom.dt, std::bind(&Custom::RobotControl, &custom));
  LoopFunc loop_udpSend("udp_send", custom.dt, 3, std::bind(&Custom::UDPSend, &custom));
  LoopFunc loop_udpRecv("udp_recv", custom.dt, 3, std::bind(&Custom::UDPRecv, &custom));
  loop_control.start();
  loop_udpSend.start();
  loop_udpRecv.start();
  while (!custom.done) usleep(10000);
  loop_control.shutdown();
  loop_udpSend.shutdown();
  loop_udpRecv.shutdown();
  std::printf("aliengo_walk: done; HighState received %u (CRC errors %u), HighCmd sent %u (send errors %u)\n",
              custom.udp.udpState.RecvCount, custom.udp.udpState.RecvCRCError, custom.udp.udpState.SendCount,
              custom.udp.udpState.SendError);
  return 0;
}
