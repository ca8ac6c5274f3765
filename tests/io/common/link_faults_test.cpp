// Client-link faults: what the decoder sees of each incoming packet, with explicit times.
#include "io/common/link_faults.hpp"

#include <gtest/gtest.h>

namespace cerebellum {
namespace {

using Packet = std::vector<std::uint8_t>;

LinkFaultRequest request(const std::string& text) {
  std::vector<std::string> words;
  std::string word;
  for (char c : text + " ") {
    if (c == ' ') {
      if (!word.empty()) words.push_back(word);
      word.clear();
    } else {
      word += c;
    }
  }
  const LinkFaultParse parsed = parse_link_fault(words);
  EXPECT_TRUE(parsed.request.has_value()) << text << ": " << parsed.error;
  return parsed.request.value_or(LinkFaultRequest{});
}

// every packet the decoder got
struct Received {
  std::vector<Packet> packets;
  LinkFaults::Deliver deliver() {
    return [this](const std::uint8_t* data, std::size_t size) { packets.emplace_back(data, data + size); };
  }
};

const Packet kPacket{1, 2, 3, 4, 5, 6, 7, 8};

TEST(LinkFaults, WithoutFaultsEveryPacketPassesOnceAndUnchanged) {
  LinkFaults link;
  Received got;
  for (int i = 0; i < 100; ++i) link.pass(kPacket.data(), kPacket.size(), i * 0.01, got.deliver());
  ASSERT_EQ(got.packets.size(), 100u);
  for (const Packet& p : got.packets) EXPECT_EQ(p, kPacket);
}

TEST(LinkFaults, DropDuplicateAndCorruptHappenAtTheirRates) {
  LinkFaults link(7);
  link.apply(request("link highlevel drop 0.3"));
  Received got;
  for (int i = 0; i < 10000; ++i) link.pass(kPacket.data(), kPacket.size(), 0.0, got.deliver());
  // 7000 expected; 5 standard deviations of a binomial(10000, 0.7) are 229
  EXPECT_NEAR(static_cast<double>(got.packets.size()), 7000.0, 229.0);
  EXPECT_EQ(link.counters().dropped, 10000u - got.packets.size());

  LinkFaults twice;
  twice.apply(request("link motor_sdk duplicate 1"));
  Received doubled;
  twice.pass(kPacket.data(), kPacket.size(), 0.0, doubled.deliver());
  ASSERT_EQ(doubled.packets.size(), 2u);
  EXPECT_EQ(doubled.packets[0], kPacket);

  LinkFaults broken;
  broken.apply(request("link aliengo corrupt 1"));
  Received corrupted;
  broken.pass(kPacket.data(), kPacket.size(), 0.0, corrupted.deliver());
  ASSERT_EQ(corrupted.packets.size(), 1u);
  int changed = 0;
  for (std::size_t i = 0; i < kPacket.size(); ++i) changed += corrupted.packets[0][i] != kPacket[i];
  EXPECT_EQ(changed, 1);
}

TEST(LinkFaults, ADelayedPacketArrivesWhenItIsDueAndInOrder) {
  LinkFaults link;
  link.apply(request("link highlevel delay 0.1"));
  Received got;
  const Packet second{9, 9};
  link.pass(kPacket.data(), kPacket.size(), 1.0, got.deliver());
  link.pass(second.data(), second.size(), 1.02, got.deliver());
  EXPECT_TRUE(got.packets.empty());
  link.release(1.0999, got.deliver());
  EXPECT_TRUE(got.packets.empty());
  link.release(1.1, got.deliver());
  ASSERT_EQ(got.packets.size(), 1u);
  link.release(1.2, got.deliver());
  ASSERT_EQ(got.packets.size(), 2u);
  EXPECT_EQ(got.packets[1], second);
  // cleared: straight through again
  link.apply(request("link highlevel clear"));
  link.pass(kPacket.data(), kPacket.size(), 2.0, got.deliver());
  EXPECT_EQ(got.packets.size(), 3u);
}

TEST(LinkFaults, TheGrammarRefusesWhatItDoesNotKnow) {
  const auto error = [](std::vector<std::string> words) { return parse_link_fault(words).error; };
  EXPECT_NE(error({"link", "wifi", "drop", "1"}).find("unknown link 'wifi' (accepted: highlevel, motor_sdk, aliengo, shm)"),
            std::string::npos);
  EXPECT_NE(error({"link", "highlevel", "jam", "1"}).find("unknown link fault 'jam'"), std::string::npos);
  EXPECT_NE(error({"link", "highlevel", "drop", "2"}).find("must be a number in [0, 1], got '2'"), std::string::npos);
  EXPECT_NE(error({"link", "highlevel", "delay", "nan"}).find("[0, 10]"), std::string::npos);
  EXPECT_NE(error({"link", "highlevel", "drop"}).find("takes one value"), std::string::npos);
  EXPECT_EQ(link_fault_text(request("link motor_sdk delay 0.25")), "link motor_sdk delay 0.25");
}

}  // namespace
}  // namespace cerebellum
