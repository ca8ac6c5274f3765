// The error of a bad configuration or scenario file: its message names the file, the key and
// what is accepted.
#pragma once

#include <stdexcept>

namespace cerebellum {

class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace cerebellum
