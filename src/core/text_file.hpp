// A whole text file read into memory, after checking its size (an oversized file is refused
// before it is read).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace cerebellum {

// the file's text, or nullopt with `error` saying why (without the path): "cannot be read: ...",
// "is N bytes, more than the limit of M", "cannot be opened"
std::optional<std::string> read_text_file(const std::string& path, std::size_t max_bytes, std::string& error);

}  // namespace cerebellum
