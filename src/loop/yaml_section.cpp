#include "loop/yaml_section.hpp"

#include <cmath>
#include <sstream>

namespace cerebellum {

std::string join_words(const std::set<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

SectionReader::SectionReader(const YAML::Node& node, std::string file, std::string section,
                             std::set<std::string> accepted, std::string kind)
    : node_(node),
      file_(std::move(file)),
      section_(std::move(section)),
      accepted_(std::move(accepted)),
      kind_(std::move(kind)) {
  if (!node_.IsMap()) fail(section_, "must be a mapping of keys (accepted: " + join_words(accepted_) + ")");
  std::set<std::string> seen;
  for (const auto& entry : node_) {
    // a key that is a list or a mapping (YAML allows it) names nothing here
    if (!entry.first.IsScalar())
      fail(section_, "has a key that is not a plain name (accepted: " + join_words(accepted_) + ")");
    const std::string key = entry.first.Scalar();
    if (!accepted_.count(key))
      fail(section_ + "." + key, "is not a known key (accepted: " + join_words(accepted_) + ")");
    // YAML parsers keep the first of two equal keys: a second one is a mistake, not an override
    if (!seen.insert(key).second) fail(section_ + "." + key, "appears twice; give each key once");
  }
}

void SectionReader::number(const std::string& key, double& value, double lower, double upper) const {
  if (!node_[key]) return;
  double parsed = 0.0;
  try {
    parsed = node_[key].as<double>();
  } catch (const YAML::Exception&) {
    fail(qualified(key),
         "must be a number in [" + format(lower) + ", " + format(upper) + "], got '" + scalar(key) + "'");
  }
  if (!std::isfinite(parsed) || parsed < lower || parsed > upper) {
    fail(qualified(key), "must be in [" + format(lower) + ", " + format(upper) + "], got " + scalar(key));
  }
  value = parsed;
}

void SectionReader::flag(const std::string& key, bool& value) const {
  if (!node_[key]) return;
  try {
    value = node_[key].as<bool>();
  } catch (const YAML::Exception&) {
    fail(qualified(key), "must be true or false, got '" + scalar(key) + "'");
  }
}

void SectionReader::unsigned_integer(const std::string& key, unsigned& value) const {
  if (!node_[key]) return;
  try {
    value = node_[key].as<unsigned>();
  } catch (const YAML::Exception&) {
    fail(qualified(key), "must be an integer >= 0, got '" + scalar(key) + "'");
  }
}

void SectionReader::unsigned_list(const std::string& key, std::vector<unsigned>& values, unsigned upper) const {
  if (!node_[key]) return;
  const YAML::Node node = node_[key];
  const std::string expected = "must be a list of whole numbers in [0, " + std::to_string(upper) + "], each once";
  if (!node.IsSequence()) fail(qualified(key), expected + ", for example [1] or [2, 3]");
  std::vector<unsigned> parsed;
  for (const YAML::Node& item : node) {
    double number = -1.0;
    if (!item.IsScalar() || !YAML::convert<double>::decode(item, number) || number != std::floor(number) ||
        number < 0.0 || number > upper) {
      fail(qualified(key), expected + ", got '" + (item.IsScalar() ? item.Scalar() : "<not a scalar>") + "'");
    }
    const auto value = static_cast<unsigned>(number);
    for (const unsigned earlier : parsed) {
      if (earlier == value) fail(qualified(key), expected + ", got " + item.Scalar() + " twice");
    }
    parsed.push_back(value);
  }
  values = parsed;
}

void SectionReader::text(const std::string& key, std::string& value, const std::set<std::string>& choices) const {
  if (!node_[key]) return;
  if (!node_[key].IsScalar()) fail(qualified(key), "must be a string");
  const std::string parsed = node_[key].as<std::string>();
  if (!choices.empty() && !choices.count(parsed)) {
    fail(qualified(key), "must be one of: " + join_words(choices) + "; got '" + parsed + "'");
  }
  value = parsed;
}

void SectionReader::path(const std::string& key, std::string& value) const {
  if (!node_[key]) return;
  const YAML::Node node = node_[key];
  if (!node.IsScalar()) fail(qualified(key), "must be a file path (a string)");
  // "?": a plain (unquoted) scalar, which YAML resolves to a number or a boolean when it reads as one
  if (node.Tag() == "?") {
    double number = 0.0;
    bool boolean = false;
    if (YAML::convert<double>::decode(node, number)) {
      fail(qualified(key),
           "must be a file path (a string), got the number " + node.Scalar() + " (quote it if a file has that name)");
    }
    if (YAML::convert<bool>::decode(node, boolean)) {
      fail(qualified(key), "must be a file path (a string), got the boolean " + node.Scalar());
    }
  }
  if (node.Scalar().empty()) fail(qualified(key), "must be a file path, got an empty string");
  value = node.Scalar();
}

void SectionReader::fail(const std::string& key, const std::string& what) const {
  throw ConfigError(kind_ + " " + file_ + ": " + key + " " + what);
}

std::string SectionReader::scalar(const std::string& key) const {
  return node_[key].IsScalar() ? node_[key].Scalar() : std::string("<not a scalar>");
}

std::string SectionReader::format(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

}  // namespace cerebellum
