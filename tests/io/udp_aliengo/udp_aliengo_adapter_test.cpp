// The AlienGo UDP endpoint on a real socket (127.0.0.1, inside a private network namespace) in
// front of the MC in lockstep: a good HighCmd is answered to its sender with a HighState carrying
// a correct CRC and the robot's state; short, long, corrupted, garbage, low-level and NaN
// datagrams are dropped and counted per reason; a 10 kHz flood from several senders leaves the
// standing robot where it is (simulator truth).
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <thread>
#include <vector>

#include "loop/simulated_robot.hpp"
#include "io/udp_aliengo/aliengo_sim.hpp"
#include "io/udp_aliengo/udp_aliengo_adapter.hpp"
#include "unitree_legged_sdk/comm.h"

namespace cerebellum {
namespace {

namespace sdk = UNITREE_LEGGED_SDK;

class Client {
 public:
  explicit Client(int port) {
    fd_ = ::socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in local{};
    local.sin_family = AF_INET;
    local.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ::bind(fd_, reinterpret_cast<sockaddr*>(&local), sizeof local);
    target_.sin_family = AF_INET;
    target_.sin_port = htons(static_cast<std::uint16_t>(port));
    target_.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  }
  ~Client() { ::close(fd_); }
  void send(const std::vector<std::uint8_t>& bytes) {
    ::sendto(fd_, bytes.data(), bytes.size(), 0, reinterpret_cast<sockaddr*>(&target_), sizeof target_);
  }
  // the next datagram within timeout_ms, or an empty vector
  std::vector<std::uint8_t> receive(int timeout_ms) {
    pollfd waiting{fd_, POLLIN, 0};
    if (::poll(&waiting, 1, timeout_ms) <= 0) return {};
    std::vector<std::uint8_t> buffer(1024);
    const ssize_t got = ::recv(fd_, buffer.data(), buffer.size(), 0);
    buffer.resize(got > 0 ? static_cast<std::size_t>(got) : 0);
    return buffer;
  }

 private:
  int fd_;
  sockaddr_in target_{};
};

std::vector<std::uint8_t> high_cmd_bytes(int mode) {
  AlienGoCommand c;
  c.mode = mode;
  std::uint8_t frame[kHighCmdBytes];
  encode_high_cmd(c, frame);
  return {frame, frame + sizeof frame};
}

struct Endpoint {
  Endpoint()
      : mc(make_simulated_mc(testing::standing_config())),
        adapter(mc.client_port(HighLevelSource::AlienGoUdp), mc.aliengo_source().inbox(), config(), stderr) {
    mc.loop().add_observer(adapter);
    run(3.0);  // the MC stands up by itself
  }
  static AlienGoUdpConfig config() {
    AlienGoUdpConfig c;
    c.bind_address = "127.0.0.1";
    c.port = 0;  // any free port
    return c;
  }
  void run(double seconds) {
    const double end = mc.backend().time_s() + seconds - 1e-9;
    while (mc.backend().time_s() < end) mc.loop().tick();
  }
  // ticks until the adapter has taken `count` datagrams (it runs on its own thread)
  bool await_received(std::uint64_t count) {
    for (int i = 0; i < 20000 && adapter.counters().received < count; ++i) {
      mc.loop().tick();
      std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
    return adapter.counters().received >= count;
  }
  Eigen::Vector3d true_position() {
    return Eigen::Map<const Eigen::Vector3d>(mc.simulation().ground_truth().position.data());
  }

  Mc mc;
  UdpAliengoAdapter adapter;
};

TEST(UdpAliengoEndpoint, AnswersAGoodHighCmdToItsSenderWithAHighStateOfTheRobot) {
  Endpoint e;
  Client client(e.adapter.port());
  client.send(high_cmd_bytes(0));
  ASSERT_TRUE(e.await_received(1));
  const std::vector<std::uint8_t> answer = client.receive(2000);
  ASSERT_EQ(answer.size(), kHighStateBytes);
  EXPECT_EQ(sdk::stored_crc(answer.data(), answer.size()), sdk::frame_crc(answer.data(), answer.size()));
  AlienGoFeedback state;
  ASSERT_TRUE(decode_high_state(answer.data(), answer.size(), state));
  EXPECT_EQ(state.mode, 0);
  // the estimate of a standing robot, near the simulator's truth
  EXPECT_NEAR(state.position.z(), e.true_position().z(), 0.03);
  EXPECT_NEAR(state.quaternion_wxyz[0], 1.0, 0.01);
  EXPECT_NEAR(state.accelerometer.z(), 9.81, 0.5);
  for (int leg = 0; leg < 4; ++leg) EXPECT_GT(state.foot_force[leg], 100) << "about 20 N per foot, in 0.1 N";
  EXPECT_EQ(e.adapter.counters().accepted, 1u);
}

TEST(UdpAliengoEndpoint, DropsAndCountsEveryKindOfBadDatagramAndTheRobotStaysPut) {
  Endpoint e;
  const Eigen::Vector3d before = e.true_position();
  Client client(e.adapter.port());
  std::vector<std::uint8_t> good = high_cmd_bytes(7);  // damping, if it were ever acted on
  std::vector<std::uint8_t> shorter(good.begin(), good.end() - 1);
  std::vector<std::uint8_t> longer = good;
  longer.push_back(0);
  std::vector<std::uint8_t> oversized(4000, 0x55);
  std::vector<std::uint8_t> bad_crc = good;
  bad_crc[10] = 2;
  std::vector<std::uint8_t> garbage(113);
  for (std::size_t i = 0; i < garbage.size(); ++i) garbage[i] = static_cast<std::uint8_t>(i * 37 + 11);
  std::vector<std::uint8_t> low_level = good;
  low_level[0] = sdk::LOWLEVEL;
  sdk::store_crc(low_level.data(), low_level.size());
  std::vector<std::uint8_t> nan = good;
  const float not_a_number = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(nan.data() + 41, &not_a_number, 4);
  sdk::store_crc(nan.data(), nan.size());
  for (const auto* bytes : {&shorter, &longer, &oversized, &bad_crc, &garbage, &low_level, &nan}) client.send(*bytes);
  client.send({});
  ASSERT_TRUE(e.await_received(8));
  e.run(1.0);
  const AlienGoCounters c = e.adapter.counters();
  EXPECT_EQ(c.wrong_length, 4u);  // short, long, oversized, empty
  EXPECT_EQ(c.bad_crc, 2u);       // flipped mode, garbage
  EXPECT_EQ(c.low_level, 1u);
  EXPECT_EQ(c.non_finite, 1u);
  EXPECT_EQ(c.accepted, 0u);
  EXPECT_EQ(client.receive(100).size(), 0u) << "dropped datagrams get no answer";
  EXPECT_NE(e.mc.machine().status().mode, static_cast<int>(ModeId::PureDamper));
  EXPECT_LT((e.true_position() - before).norm(), 0.02);
}

TEST(UdpAliengoEndpoint, AFloodFromSeveralSendersAtTenKilohertzLeavesTheRobotStanding) {
  Endpoint e;
  const Eigen::Vector3d before = e.true_position();
  const int port = e.adapter.port();
  std::atomic<bool> flooding{true};
  std::atomic<std::uint64_t> sent{0};
  std::vector<std::thread> senders;
  for (int s = 0; s < 4; ++s) {
    senders.emplace_back([&, s] {
      Client client(port);
      std::vector<std::uint8_t> junk(113 + s, static_cast<std::uint8_t>(s));
      const std::vector<std::uint8_t> idle = high_cmd_bytes(0);
      auto next = std::chrono::steady_clock::now();
      for (int i = 0; flooding.load(); ++i) {
        // each sender 2.5 kHz: garbage and idle commands (a robot told to stand keeps standing)
        client.send(i % 2 == 0 ? junk : idle);
        sent.fetch_add(1);
        next += std::chrono::microseconds(400);
        std::this_thread::sleep_until(next);
      }
    });
  }
  // at least 2 s of robot time in lockstep, paced near real time so the flood meets a running
  // loop, and on until the adapter has read 2000 datagrams of it (however fast this machine is)
  for (int i = 0; i < 1000 || e.adapter.counters().received < 2000; ++i) {
    e.mc.loop().tick();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  flooding.store(false);
  for (auto& t : senders) t.join();
  e.run(0.5);
  e.adapter.finish(stderr);  // its thread stopped: the counters are final and agree with each other
  const AlienGoCounters c = e.adapter.counters();
  EXPECT_GE(sent.load(), c.received);
  EXPECT_EQ(c.accepted + c.wrong_length + c.bad_crc, c.received);
  EXPECT_GT(c.states_sent, 0u);
  EXPECT_GT(e.mc.simulation().ground_truth().position[2], 0.2);
  EXPECT_LT((e.true_position() - before).head<2>().norm(), 0.05);
}

// a client streaming as fast as its thread can send (faster than the adapter reads): every
// command is stamped with the robot time when it is read, so the stream never looks silent, and
// what the loop cannot take is dropped and counted as this client's own
TEST(UdpAliengoEndpoint, AStreamFasterThanTheAdapterReadsKeepsItsRobotStandingAndNeverTimesOut) {
  Endpoint e;
  const int port = e.adapter.port();
  std::atomic<bool> flooding{true};
  std::thread sender([&] {
    Client client(port);
    const std::vector<std::uint8_t> stand = high_cmd_bytes(static_cast<int>(AlienGoMode::ForceStand));
    while (flooding.load()) client.send(stand);
  });
  ASSERT_TRUE(e.await_received(1000));
  // 3 s of robot time (six heartbeat timeouts); before each tick the adapter has read more of the
  // stream (so a loaded machine that starves its thread cannot make the client look silent)
  for (int i = 0; i < 1500; ++i) {
    const std::uint64_t read = e.adapter.counters().received;
    while (e.adapter.counters().received == read) std::this_thread::sleep_for(std::chrono::microseconds(100));
    e.mc.loop().tick();
  }
  flooding.store(false);
  sender.join();
  e.adapter.finish(stderr);  // its thread stopped: the counters are final and agree with each other
  const AlienGoCounters c = e.adapter.counters();
  EXPECT_EQ(c.timeouts, 0u) << "a streaming client was judged silent";
  EXPECT_EQ(e.mc.machine().holder(), HighLevelSource::AlienGoUdp);
  EXPECT_NE(e.mc.machine().status().mode, static_cast<int>(ModeId::PureDamper));
  EXPECT_GT(e.mc.simulation().ground_truth().position[2], 0.2) << "the robot still stands (truth)";
  EXPECT_EQ(c.accepted, c.received);
}

}  // namespace
}  // namespace cerebellum
