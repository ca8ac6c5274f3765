// The YAML configuration file: loads, or fails with a ConfigError naming the problem; never
// another exception, never a crash.
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "loop/mc_config.hpp"
#include "fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/tmp/cerebellum_fuzz_config_" + std::to_string(::getpid()) + ".yaml";
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    (void)cerebellum::load_config(path);
  } catch (const cerebellum::ConfigError&) {
  }
  return 0;
}
