#include "motions/user_gait_store.hpp"

namespace cerebellum {

void UserGaitStore::store(const UserGaitFile& file) {
  const std::lock_guard lock(mutex_);
  if (file.kind == UserGaitFile::Kind::Definition) {
    definition_ = file.definition;
  } else {
    parameters_ = file.parameters;
  }
  ++version_;
}

std::optional<UserGaitDefinition> UserGaitStore::definition() const {
  const std::lock_guard lock(mutex_);
  return definition_;
}

std::optional<UserGaitParameters> UserGaitStore::parameters() const {
  const std::lock_guard lock(mutex_);
  return parameters_;
}

std::uint64_t UserGaitStore::version() const {
  const std::lock_guard lock(mutex_);
  return version_;
}

}  // namespace cerebellum
