// Object name prefixes unique to one test in one process, so tests can run in parallel.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <string>

namespace cerebellum {

inline std::string unique_shm_prefix() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string(info->test_suite_name()) + "_" + info->name();
  for (char& c : name) {
    if (c == '/') c = '_';
  }
  std::string prefix = "cbtest";
  prefix += std::to_string(::getpid());
  prefix += "_";
  prefix += name.substr(0, 40);
  prefix += "_";
  return prefix;
}

// "/" + the unique prefix + suffix
inline std::string unique_shm_object_name(const std::string& suffix) {
  std::string name = "/";
  name += unique_shm_prefix();
  name += suffix;
  return name;
}

inline bool shm_object_exists(const std::string& name) { return ::access(("/dev/shm" + name).c_str(), F_OK) == 0; }

}  // namespace cerebellum
