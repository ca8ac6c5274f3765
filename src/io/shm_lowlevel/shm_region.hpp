// One POSIX shared-memory object owned by the MC: created (or taken back from an earlier run of
// the same user) with exact permission bits, sized, zeroed and mapped; locked against a second
// MC on the same name; unlinked on destruction.
#pragma once

#include <optional>

#include <cstddef>
#include <string>

namespace cerebellum {

class ShmRegion {
 public:
  // name: "/something"; mode: permission bits, set exactly (the umask does not reduce them).
  // throws std::runtime_error naming the object and the failing call
  // group_id: the object's owner group (none: the process's)
  ShmRegion(std::string name, std::size_t size_bytes, unsigned mode, std::optional<unsigned> group_id = std::nullopt);
  ~ShmRegion();
  ShmRegion(const ShmRegion&) = delete;
  ShmRegion& operator=(const ShmRegion&) = delete;

  void* data() const { return data_; }
  std::size_t size_bytes() const { return size_bytes_; }
  const std::string& name() const { return name_; }

 private:
  std::string name_;
  std::size_t size_bytes_;
  void* data_ = nullptr;
  int fd_ = -1;  // held open for the lock
};

}  // namespace cerebellum
