#include "unitree_legged_sdk/udp.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace UNITREE_LEGGED_SDK {

UDP::UDP(uint16_t localPort, const char* targetIP, uint16_t targetPort, int sendLength, int recvLength, int useTimeOut)
    : send_length_(sendLength),
      recv_length_(recvLength),
      timeout_ms_(useTimeOut),
      send_buffer_(static_cast<std::size_t>(sendLength > 0 ? sendLength : 0)),
      recv_frame_(static_cast<std::size_t>(recvLength > 0 ? recvLength : 0)),
      scratch_(2048) {
  if (sendLength < 8 || recvLength < 8) throw std::invalid_argument("UDP: frame lengths must be at least 8 bytes");
  sockaddr_in target{};
  target.sin_family = AF_INET;
  target.sin_port = htons(targetPort);
  if (inet_pton(AF_INET, targetIP, &target.sin_addr) != 1) {
    throw std::invalid_argument(std::string("UDP: not an IPv4 address: ") + targetIP);
  }
  target_address_.resize(sizeof target);
  std::memcpy(target_address_.data(), &target, sizeof target);

  socket_ = ::socket(AF_INET, SOCK_DGRAM, 0);
  if (socket_ < 0) throw std::runtime_error(std::string("UDP: socket: ") + std::strerror(errno));
  const int yes = 1;
  ::setsockopt(socket_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  sockaddr_in local{};
  local.sin_family = AF_INET;
  local.sin_port = htons(localPort);
  local.sin_addr.s_addr = htonl(INADDR_ANY);
  if (::bind(socket_, reinterpret_cast<const sockaddr*>(&local), sizeof local) != 0) {
    const std::string reason = std::strerror(errno);
    ::close(socket_);
    throw std::runtime_error("UDP: cannot bind local port " + std::to_string(localPort) + ": " + reason);
  }
  ::fcntl(socket_, F_SETFL, ::fcntl(socket_, F_GETFL) | O_NONBLOCK);
}

UDP::~UDP() {
  if (socket_ >= 0) ::close(socket_);
}

void UDP::InitCmdData(HighCmd& cmd) { cmd.levelFlag = HIGHLEVEL; }

void UDP::SetSend(HighCmd& cmd) {
  store_crc(&cmd, sizeof cmd);
  std::lock_guard<std::mutex> lock(mutex_);
  std::memset(send_buffer_.data(), 0, send_buffer_.size());
  std::memcpy(send_buffer_.data(), &cmd, std::min(send_buffer_.size(), sizeof cmd));
}

int UDP::Send() {
  std::vector<uint8_t> frame;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    frame = send_buffer_;
  }
  ++udpState.TotalCount;
  const ssize_t sent =
      ::sendto(socket_, frame.data(), frame.size(), 0, reinterpret_cast<const sockaddr*>(target_address_.data()),
               static_cast<socklen_t>(target_address_.size()));
  if (sent < 0) {
    ++udpState.SendError;
    return -1;
  }
  ++udpState.SendCount;
  return static_cast<int>(sent);
}

int UDP::Recv() {
  ++udpState.TotalCount;
  if (timeout_ms_ >= 0) {
    pollfd waiting{socket_, POLLIN, 0};
    ::poll(&waiting, 1, timeout_ms_);
  }
  int newest = 0;
  bool any = false;
  for (;;) {
    const ssize_t got = ::recv(socket_, scratch_.data(), scratch_.size(), 0);
    if (got < 0) {
      if (errno == EAGAIN || errno == EWOULDBLOCK) break;
      if (errno == EINTR) continue;
      return -1;
    }
    any = true;
    newest = static_cast<int>(got);
    if (got != recv_length_) {
      ++udpState.FlagError;
      continue;
    }
    if (stored_crc(scratch_.data(), static_cast<std::size_t>(got)) !=
        frame_crc(scratch_.data(), static_cast<std::size_t>(got))) {
      ++udpState.RecvCRCError;
      continue;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    std::memcpy(recv_frame_.data(), scratch_.data(), recv_frame_.size());
    ++udpState.RecvCount;
  }
  if (!any) ++udpState.RecvLoseError;
  return newest;
}

void UDP::GetRecv(HighState& state) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::memset(&state, 0, sizeof state);
  std::memcpy(&state, recv_frame_.data(), std::min(recv_frame_.size(), sizeof state));
}

}  // namespace UNITREE_LEGGED_SDK
