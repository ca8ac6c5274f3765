#include "core/text_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace cerebellum {

std::optional<std::string> read_text_file(const std::string& path, std::size_t max_bytes, std::string& error) {
  std::error_code code;
  const std::uintmax_t size = std::filesystem::file_size(path, code);
  if (code) {
    error = "cannot be read: " + code.message();
    return std::nullopt;
  }
  if (size > max_bytes) {
    error = "is " + std::to_string(size) + " bytes, more than the limit of " + std::to_string(max_bytes);
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = "cannot be opened";
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace cerebellum
