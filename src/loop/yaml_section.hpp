// One mapping of a YAML file read strictly: unknown and repeated keys, values of the wrong type
// or out of range are errors that name the file, the key and what was expected (ConfigError).
// Used by the MC's configuration and the fault scenario files.
#pragma once

#include <yaml-cpp/yaml.h>

#include <set>
#include <string>
#include <vector>

#include "loop/config_error.hpp"

namespace cerebellum {

// "a, b, c"
std::string join_words(const std::set<std::string>& words);

class SectionReader {
 public:
  // kind: what the file is, for messages ("config", "fault scenario")
  SectionReader(const YAML::Node& node, std::string file, std::string section, std::set<std::string> accepted,
                std::string kind = "config");

  bool has(const std::string& key) const { return static_cast<bool>(node_[key]); }
  void number(const std::string& key, double& value, double lower, double upper) const;
  void flag(const std::string& key, bool& value) const;
  void unsigned_integer(const std::string& key, unsigned& value) const;
  // a list of whole numbers in [0, upper], each at most once (for example CPUs)
  void unsigned_list(const std::string& key, std::vector<unsigned>& values, unsigned upper) const;
  void text(const std::string& key, std::string& value, const std::set<std::string>& choices = {}) const;
  // a file's path: a string; an unquoted number or true/false (YAML's other plain scalars) is refused,
  // since no one means the file "42"
  void path(const std::string& key, std::string& value) const;
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;

 private:
  std::string qualified(const std::string& key) const { return section_ + "." + key; }
  std::string scalar(const std::string& key) const;
  static std::string format(double v);

  YAML::Node node_;
  std::string file_;
  std::string section_;
  std::set<std::string> accepted_;
  std::string kind_;
};

}  // namespace cerebellum
