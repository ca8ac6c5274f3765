// Configuration of the shared-memory low-level interface (config section `shm:`).
#pragma once

#include <optional>
#include <string>

namespace cerebellum {

struct ShmLowLevelConfig {
  bool enabled = true;  // the objects are local to this host by nature
  // the objects are "/" + name_prefix + "spline_shm" and "/" + name_prefix + "imu_shm"; empty
  // gives the vendor's names, a prefix lets several MCs (or parallel tests) share one host
  std::string name_prefix;
  // permission bits of both objects: the MC's user and group by default, never umask-reduced
  unsigned mode = 0660;
  // owner group of both objects (with mode 0660: the users who may write commands); none: the
  // MC's own group
  std::optional<unsigned> group_id;
  // 1 ms cycles without a new command frame before the command is dropped for damping
  int command_timeout_cycles = 10;
};

std::string shm_spline_object_name(const std::string& name_prefix);
std::string shm_imu_object_name(const std::string& name_prefix);

// empty when usable, else what is wrong (accepted: letters, digits, '_', '-', '.'; <= 64 chars)
std::string shm_name_prefix_problem(const std::string& name_prefix);
// "0660" or "660": octal permission bits in [0, 0777] that include owner read and write
std::optional<unsigned> parse_shm_mode(const std::string& text);
// the id of a group given by name or number, when this system knows it
std::optional<unsigned> find_group_id(const std::string& group);

}  // namespace cerebellum
