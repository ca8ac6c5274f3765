// A scan of a TOML text's shape before the parser sees it. toml++ parses dotted keys and nested
// arrays / inline tables recursively, so a small text with a key 40,000 parts deep overflows the
// stack of the thread that parses it (a user_gait_file packet could stop the MC). A valid gait file
// needs a table header and one level of arrays (so does a motion file); anything far deeper is
// refused here.
#pragma once

#include <string>
#include <string_view>

namespace cerebellum {

struct TomlShapeLimits {
  int max_key_parts = 16;  // a.b.c = 1 has 3; so do [a.b.c] and "a"."b"."c"
  int max_nesting = 16;    // open [ and { at once, table headers included ([[step]] is 2)
};

// empty when the text is within the limits, else what is too deep and on which line
std::string toml_shape_problem(std::string_view text, const TomlShapeLimits& limits = {});

}  // namespace cerebellum
