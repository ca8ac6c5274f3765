#include "io/shm_lowlevel_robot/shm_mapping.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace cerebellum {

std::unique_ptr<ShmMapping> ShmMapping::open_existing(const std::string& name, std::size_t needed_bytes,
                                                      std::string& why) {
  const int fd = ::shm_open(name.c_str(), O_RDWR, 0);
  if (fd < 0) {
    why = errno == ENOENT ? name + " does not exist (is the daemon running?)"
                          : name + ": shm_open: " + std::strerror(errno);
    return nullptr;
  }
  struct stat info {};
  if (::fstat(fd, &info) != 0) {
    why = name + ": fstat: " + std::strerror(errno);
    ::close(fd);
    return nullptr;
  }
  const auto size_bytes = static_cast<std::size_t>(info.st_size);
  if (size_bytes < needed_bytes) {
    why = name + " is " + std::to_string(size_bytes) + " bytes, lowlevel.h needs " + std::to_string(needed_bytes) +
          " (the daemon has not sized it yet, or it is not the daemon's)";
    ::close(fd);
    return nullptr;
  }
  void* mapped = ::mmap(nullptr, size_bytes, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  const int map_error = errno;
  ::close(fd);  // the mapping keeps the object
  if (mapped == MAP_FAILED) {
    why = name + ": mmap: " + std::strerror(map_error);
    return nullptr;
  }
  return std::unique_ptr<ShmMapping>(new ShmMapping(name, mapped, size_bytes));
}

ShmMapping::~ShmMapping() { ::munmap(data_, size_bytes_); }

}  // namespace cerebellum
