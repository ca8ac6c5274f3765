// The lease of the high-level clients, judged by each client's own receive times.
#include "modes/source_lease.hpp"

#include <gtest/gtest.h>

namespace cerebellum {
namespace {

constexpr auto kLcm = HighLevelSource::CyberDog2Lcm;
constexpr auto kAlienGo = HighLevelSource::AlienGoUdp;
using Verdict = SourceLease::Verdict;

TEST(SourceLease, TheFirstClientHoldsAndTheOtherIsRefusedWhileTheHolderSpeaks) {
  SourceLease lease(0.5);
  EXPECT_FALSE(lease.holder().has_value());
  EXPECT_EQ(lease.judge(kAlienGo, 1.0), Verdict::Holds);
  EXPECT_EQ(lease.judge(kLcm, 1.2), Verdict::Refused);
  EXPECT_EQ(lease.judge(kAlienGo, 1.4), Verdict::Holds);
  EXPECT_EQ(lease.judge(kLcm, 1.9), Verdict::Refused) << "0.5 s after the holder's last command, not yet past";
  EXPECT_EQ(lease.holder(), kAlienGo);
}

TEST(SourceLease, TheOtherClientTakesOverOnceTheHolderIsSilentPastTheTimeout) {
  SourceLease lease(0.5);
  lease.judge(kLcm, 0.0);
  // the other client's own traffic never keeps the holder's lease alive
  for (double t = 0.1; t < 0.5; t += 0.1) EXPECT_EQ(lease.judge(kAlienGo, t), Verdict::Refused);
  EXPECT_EQ(lease.judge(kAlienGo, 0.51), Verdict::TakesOver);
  EXPECT_EQ(lease.holder(), kAlienGo);
  EXPECT_EQ(lease.judge(kLcm, 0.6), Verdict::Refused);
}

}  // namespace
}  // namespace cerebellum
