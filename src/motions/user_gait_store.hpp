// The newest validated user gait definition and parameters, kept for the locomotion mode that will
// run them (mode 11 / 62, gait 110). Written by the interface thread, read by anyone.
#pragma once

#include <cstdint>
#include <mutex>
#include <optional>

#include "motions/user_gait_file.hpp"

namespace cerebellum {

class UserGaitStore {
 public:
  void store(const UserGaitFile& file);

  std::optional<UserGaitDefinition> definition() const;
  std::optional<UserGaitParameters> parameters() const;
  // files stored so far (changes whenever either part is replaced)
  std::uint64_t version() const;

 private:
  mutable std::mutex mutex_;
  std::optional<UserGaitDefinition> definition_;
  std::optional<UserGaitParameters> parameters_;
  std::uint64_t version_ = 0;
};

}  // namespace cerebellum
