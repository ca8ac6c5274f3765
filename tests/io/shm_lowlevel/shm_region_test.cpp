// The MC's shared-memory objects: exact permissions, zeroed content, taken back only from the
// same user, removed on destruction.
#include "io/shm_lowlevel/shm_region.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <stdexcept>

#include "io/shm_lowlevel/shm_lowlevel_config.hpp"
#include "io/shm_lowlevel/shm_test_names.hpp"

namespace cerebellum {
namespace {

mode_t permission_bits(const std::string& name) {
  struct stat info {};
  EXPECT_EQ(::stat(("/dev/shm" + name).c_str(), &info), 0) << name;
  return info.st_mode & 07777;
}

// an object left behind by someone else: mode 0600, filled with 0xab
void leave_stale_object(const std::string& name, std::size_t size) {
  const int fd = ::shm_open(name.c_str(), O_CREAT | O_RDWR, 0600);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::ftruncate(fd, static_cast<off_t>(size)), 0);
  void* memory = ::mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  ASSERT_NE(memory, MAP_FAILED);
  std::memset(memory, 0xab, size);
  ::munmap(memory, size);
  ::close(fd);
}

TEST(ShmRegion, PermissionsAreExactWhateverTheUmask) {
  const std::string name = unique_shm_object_name("obj");
  const mode_t old_umask = ::umask(077);
  {
    ShmRegion region(name, 10240, 0660);
    EXPECT_EQ(permission_bits(name), 0660u);
  }
  {
    ShmRegion region(name, 1024, 0666);
    EXPECT_EQ(permission_bits(name), 0666u);
  }
  ::umask(old_umask);
}

TEST(ShmRegion, SizedZeroedAndRemovedOnDestruction) {
  const std::string name = unique_shm_object_name("obj");
  leave_stale_object(name, 64);
  {
    ShmRegion region(name, 10240, 0660);
    EXPECT_EQ(region.size_bytes(), 10240u);
    struct stat info {};
    ASSERT_EQ(::stat(("/dev/shm" + name).c_str(), &info), 0);
    EXPECT_EQ(info.st_size, 10240);
    EXPECT_EQ(permission_bits(name), 0660u);  // the stale 0600 replaced
    const auto* bytes = static_cast<const unsigned char*>(region.data());
    for (std::size_t i = 0; i < region.size_bytes(); ++i) ASSERT_EQ(bytes[i], 0) << i;
  }
  EXPECT_FALSE(shm_object_exists(name));
}

TEST(ShmRegion, ObjectOfAnotherUserIsRefusedAndLeftAlone) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to give an object to another user";
  const std::string name = unique_shm_object_name("obj");
  leave_stale_object(name, 64);
  ASSERT_EQ(::chown(("/dev/shm" + name).c_str(), 4242, 4242), 0);
  try {
    ShmRegion region(name, 1024, 0660);
    ADD_FAILURE() << "took over an object of uid 4242";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("belongs to uid 4242"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(shm_object_exists(name));
  EXPECT_EQ(permission_bits(name), 0600u);
  ::shm_unlink(name.c_str());
}

TEST(ShmRegion, SecondOwnerOfALiveObjectIsRefused) {
  const std::string name = unique_shm_object_name("obj");
  ShmRegion first(name, 1024, 0660);
  static_cast<unsigned char*>(first.data())[7] = 42;
  try {
    ShmRegion second(name, 1024, 0660);
    ADD_FAILURE() << "two owners of " << name;
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("already served by another running MC"), std::string::npos) << e.what();
  }
  // the first owner's object is untouched
  EXPECT_TRUE(shm_object_exists(name));
  EXPECT_EQ(static_cast<unsigned char*>(first.data())[7], 42);
}

TEST(ShmRegion, TheConfiguredGroupOwnsTheObject) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to give an object to another group";
  const std::optional<unsigned> daemon = find_group_id("daemon");
  ASSERT_TRUE(daemon.has_value());
  const std::string name = "/" + unique_shm_prefix() + "group";
  ShmRegion region(name, 1024, 0660, daemon);
  struct stat info {};
  ASSERT_EQ(::stat(("/dev/shm" + name).c_str(), &info), 0);
  EXPECT_EQ(info.st_gid, *daemon);
  EXPECT_EQ(info.st_mode & 0777, 0660u);
}

TEST(ShmRegion, BadNameIsReported) { EXPECT_THROW(ShmRegion("/no/slashes/inside", 1024, 0660), std::runtime_error); }

}  // namespace
}  // namespace cerebellum
