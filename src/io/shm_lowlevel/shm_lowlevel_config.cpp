#include "io/shm_lowlevel/shm_lowlevel_config.hpp"

#include <grp.h>

#include <array>

namespace cerebellum {

std::string shm_spline_object_name(const std::string& name_prefix) { return "/" + name_prefix + "spline_shm"; }

std::string shm_imu_object_name(const std::string& name_prefix) { return "/" + name_prefix + "imu_shm"; }

std::string shm_name_prefix_problem(const std::string& name_prefix) {
  if (name_prefix.size() > 64) return "is longer than 64 characters";
  for (const char c : name_prefix) {
    const bool allowed =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
    if (!allowed) return std::string("contains '") + c + "' (accepted: letters, digits, '_', '-', '.')";
  }
  return {};
}

std::optional<unsigned> parse_shm_mode(const std::string& text) {
  if (text.empty() || text.size() > 4) return std::nullopt;
  unsigned mode = 0;
  for (const char c : text) {
    if (c < '0' || c > '7') return std::nullopt;
    mode = mode * 8 + static_cast<unsigned>(c - '0');
  }
  constexpr unsigned kOwnerReadWrite = 0600;
  if (mode > 0777 || (mode & kOwnerReadWrite) != kOwnerReadWrite) return std::nullopt;
  return mode;
}

std::optional<unsigned> find_group_id(const std::string& group) {
  if (group.empty()) return std::nullopt;
  struct group entry {};
  struct group* found = nullptr;
  std::array<char, 4096> buffer{};
  if (group.find_first_not_of("0123456789") == std::string::npos && group.size() <= 9) {
    const auto id = static_cast<gid_t>(std::stoul(group));
    if (::getgrgid_r(id, &entry, buffer.data(), buffer.size(), &found) == 0 && found != nullptr) return id;
    return std::nullopt;
  }
  if (::getgrnam_r(group.c_str(), &entry, buffer.data(), buffer.size(), &found) == 0 && found != nullptr) {
    return found->gr_gid;
  }
  return std::nullopt;
}

}  // namespace cerebellum
