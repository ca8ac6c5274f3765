#include "io/shm_lowlevel/shm_region.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace cerebellum {
namespace {

[[noreturn]] void fail(const std::string& name, const std::string& what, int error) {
  throw std::runtime_error("shared memory " + name + ": " + what + ": " + std::strerror(error));
}

// closes the descriptor when the constructor fails
class FdGuard {
 public:
  explicit FdGuard(int fd) : fd_(fd) {}
  ~FdGuard() {
    if (fd_ >= 0) ::close(fd_);
  }
  FdGuard(const FdGuard&) = delete;
  FdGuard& operator=(const FdGuard&) = delete;
  int release() {
    const int fd = fd_;
    fd_ = -1;
    return fd;
  }

 private:
  int fd_;
};

}  // namespace

ShmRegion::ShmRegion(std::string name, std::size_t size_bytes, unsigned mode, std::optional<unsigned> group_id)
    : name_(std::move(name)), size_bytes_(size_bytes) {
  const int fd = ::shm_open(name_.c_str(), O_CREAT | O_RDWR, static_cast<mode_t>(mode));
  if (fd < 0) fail(name_, "shm_open", errno);
  FdGuard guard(fd);
  // a client started first, or an earlier run that crashed, may have left the object: take it
  // over only when it is ours, so nobody else decides its permissions or content
  struct stat info {};
  if (::fstat(fd, &info) != 0) fail(name_, "fstat", errno);
  if (info.st_uid != ::geteuid()) {
    throw std::runtime_error("shared memory " + name_ + ": exists and belongs to uid " + std::to_string(info.st_uid) +
                             "; remove /dev/shm" + name_ + " or choose another shm.name_prefix");
  }
  // the lock lives as long as the descriptor: a second MC on the same names stops here instead
  // of zeroing the objects under the first one (clients never lock)
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    throw std::runtime_error("shared memory " + name_ +
                             ": already served by another running MC; choose another "
                             "shm.name_prefix");
  }
  // from here on the object is ours: remove it again when it cannot be set up
  auto fail_and_unlink = [this](const char* call) {
    const int error = errno;
    ::shm_unlink(name_.c_str());
    fail(name_, call, error);
  };
  if (::fchmod(fd, static_cast<mode_t>(mode)) != 0) fail_and_unlink("fchmod");
  if (group_id && ::fchown(fd, static_cast<uid_t>(-1), static_cast<gid_t>(*group_id)) != 0) fail_and_unlink("fchown");
  if (::ftruncate(fd, static_cast<off_t>(size_bytes_)) != 0) fail_and_unlink("ftruncate");
  void* mapped = ::mmap(nullptr, size_bytes_, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  if (mapped == MAP_FAILED) fail_and_unlink("mmap");
  data_ = mapped;
  std::memset(data_, 0, size_bytes_);
  fd_ = guard.release();
}

ShmRegion::~ShmRegion() {
  ::munmap(data_, size_bytes_);
  ::shm_unlink(name_.c_str());
  ::close(fd_);
}

}  // namespace cerebellum
