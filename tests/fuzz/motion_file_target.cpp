// motion files (TOML): a motion with finite fields and timed steps, or refused with a reason.
#include <cmath>
#include <string_view>

#include "fuzz_target.hpp"
#include "motions/motion_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const cerebellum::MotionFileParse parsed = cerebellum::parse_motion_file(text);
  FUZZ_CHECK(parsed.motion.has_value() != !parsed.error.empty());
  if (parsed.motion) {
    FUZZ_CHECK(!parsed.motion->steps.empty() && parsed.motion->steps.size() <= cerebellum::kMaxMotionSteps);
    for (const auto& step : parsed.motion->steps) {
      FUZZ_CHECK(step.duration >= 1 && step.duration <= cerebellum::kMaxMotionStepMs);
      for (float v : step.rpy_des) FUZZ_CHECK(std::isfinite(v));
      for (float v : step.foot_pose) FUZZ_CHECK(std::isfinite(v));
    }
  }
  return 0;
}
