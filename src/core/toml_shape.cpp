#include "core/toml_shape.hpp"

namespace cerebellum {
namespace {

bool starts_with(std::string_view text, std::size_t at, std::string_view prefix) {
  return text.substr(at, prefix.size()) == prefix;
}

// the index just past the string that starts at `at` (a quote), or text.size() when unterminated;
// counts the newlines it crosses
std::size_t skip_string(std::string_view text, std::size_t at, int& line) {
  const char quote = text[at];
  const bool literal = quote == '\'';
  const std::string_view triple = literal ? "'''" : "\"\"\"";
  const bool multi_line = starts_with(text, at, triple);
  std::size_t i = at + (multi_line ? 3 : 1);
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\\' && !literal) {
      i += 2;
      continue;
    }
    if (c == '\n') {
      ++line;
      if (!multi_line) return i;  // unterminated: the parser reports it
    }
    if (multi_line ? starts_with(text, i, triple) : c == quote) return i + (multi_line ? 3 : 1);
    ++i;
  }
  return text.size();
}

std::string problem_at(int line, const std::string& what) { return "line " + std::to_string(line) + ": " + what; }

}  // namespace

std::string toml_shape_problem(std::string_view text, const TomlShapeLimits& limits) {
  int line = 1;
  int nesting = 0;
  int dots_in_chain = 0;  // dots since the last token that cannot be inside one key or number
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '"' || c == '\'') {
      i = skip_string(text, i, line);
      continue;
    }
    if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
      continue;
    }
    switch (c) {
      case '\n':
        ++line;
        dots_in_chain = 0;
        break;
      case '.':
        if (++dots_in_chain >= limits.max_key_parts) {
          return problem_at(line, "a dotted key with more than " + std::to_string(limits.max_key_parts) +
                                      " parts (a gait file needs a few)");
        }
        break;
      case '[':
      case '{':
        dots_in_chain = 0;
        if (++nesting > limits.max_nesting) {
          return problem_at(line, "arrays, tables or inline tables nested more than " +
                                      std::to_string(limits.max_nesting) + " deep (a gait file needs 2)");
        }
        break;
      case ']':
      case '}':
        dots_in_chain = 0;
        if (nesting > 0) --nesting;
        break;
      case '=':
      case ',': dots_in_chain = 0; break;
      default: break;
    }
    ++i;
  }
  return {};
}

}  // namespace cerebellum
