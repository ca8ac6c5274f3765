// A POSIX shared-memory object another process owns (the ZsiBot's daemon), mapped read-write by
// its client: never created (a client that created it would wait on memory no daemon writes),
// never resized nor unlinked; unmapped on destruction.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

namespace cerebellum {

class ShmMapping {
 public:
  // the object mapped, or nullptr with why (it does not exist yet, is smaller than needed_bytes,
  // or may not be opened)
  static std::unique_ptr<ShmMapping> open_existing(const std::string& name, std::size_t needed_bytes,
                                                   std::string& why);
  ~ShmMapping();
  ShmMapping(const ShmMapping&) = delete;
  ShmMapping& operator=(const ShmMapping&) = delete;

  void* data() const { return data_; }
  const std::string& name() const { return name_; }

 private:
  ShmMapping(std::string name, void* data, std::size_t size_bytes)
      : name_(std::move(name)), data_(data), size_bytes_(size_bytes) {}

  std::string name_;
  void* data_;
  std::size_t size_bytes_;
};

}  // namespace cerebellum
