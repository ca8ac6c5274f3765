// user_gait_file texts (TOML): valid, or refused with a reason; a stored gait has finite numbers.
#include <cmath>
#include <string_view>

#include "fuzz_target.hpp"
#include "motions/user_gait_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const cerebellum::UserGaitParse parsed = cerebellum::parse_user_gait_file(text);
  FUZZ_CHECK(parsed.file.has_value() || !parsed.error.empty());
  if (parsed.file && parsed.file->kind == cerebellum::UserGaitFile::Kind::Parameters) {
    for (const auto& step : parsed.file->parameters.steps) {
      for (float v : step.vel_des) FUZZ_CHECK(std::isfinite(v));
    }
  }
  return 0;
}
