// The AlienGo SDK's UDP link, written from docs/aliengo-udp.md: one socket bound to a local port,
// frames sent to the robot's address and port, the newest received frame kept after its CRC check.
#pragma once

#include <cstdint>
#include <mutex>
#include <vector>

#include "unitree_legged_sdk/comm.h"

namespace UNITREE_LEGGED_SDK {

struct UDPState {
  uint32_t TotalCount = 0;     // Send() and Recv() calls
  uint32_t SendCount = 0;      // frames sent
  uint32_t RecvCount = 0;      // frames received with a good CRC
  uint32_t SendError = 0;      // sendto failed
  uint32_t FlagError = 0;      // received frames of another level (levelFlag) or length
  uint32_t RecvCRCError = 0;   // received frames with a bad CRC (the old state is kept)
  uint32_t RecvLoseError = 0;  // Recv() calls that found no frame
};

class UDP {
 public:
  // useTimeOut: < 0 Recv() never waits; >= 0 it waits up to that many milliseconds for a frame
  UDP(uint16_t localPort, const char* targetIP, uint16_t targetPort, int sendLength, int recvLength,
      int useTimeOut = -1);
  ~UDP();
  UDP(const UDP&) = delete;
  UDP& operator=(const UDP&) = delete;

  // sets the level flag of a fresh command (high level)
  void InitCmdData(HighCmd& cmd);
  // fills cmd.crc (in the caller's struct) and copies the frame to the send buffer
  void SetSend(HighCmd& cmd);
  // sends the send buffer; the bytes sent, or -1
  int Send();
  // drains the socket and keeps the newest frame whose CRC holds; the bytes of the newest frame
  // read, 0 when none arrived, -1 on a socket error
  int Recv();
  // copies the newest good frame (zeros before the first)
  void GetRecv(HighState& state);

  UDPState udpState;

 private:
  int socket_ = -1;
  std::vector<uint8_t> target_address_;  // sockaddr_in
  int send_length_;
  int recv_length_;
  int timeout_ms_;
  std::mutex mutex_;
  std::vector<uint8_t> send_buffer_;
  std::vector<uint8_t> recv_frame_;  // the newest good frame
  std::vector<uint8_t> scratch_;
};

}  // namespace UNITREE_LEGGED_SDK
