// The include rules of docs/architecture.md, checked on every file under src/: dependencies point
// inward, and vendor wire types stay at the edge.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace cerebellum {
namespace {

namespace fs = std::filesystem;

struct Include {
  std::string file;  // relative to src/
  int line = 0;
  std::string target;  // as written between the quotes
};

// every #include "..." of every source file under src/
std::vector<Include> project_includes() {
  const fs::path src = fs::path(CEREBELLUM_SOURCE_DIR) / "src";
  const std::regex include(R"re(^\s*#\s*include\s*"([^"]+)")re");
  std::vector<Include> found;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(src)) {
    const std::string extension = entry.path().extension().string();
    if (!entry.is_regular_file() || (extension != ".hpp" && extension != ".cpp" && extension != ".h")) continue;
    std::ifstream in(entry.path());
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
      std::smatch match;
      if (std::regex_search(text, match, include)) {
        found.push_back({fs::relative(entry.path(), src).generic_string(), line, match[1].str()});
      }
    }
  }
  return found;
}

bool in_folder(const std::string& path, const std::string& folder) { return path.rfind(folder + "/", 0) == 0; }

// a vendor wire type: an lcm-gen header or the shared-memory interface's C header
bool is_wire_type(const std::string& target) {
  static const std::regex wire(R"((_lcmt|_t)\.hpp$|^lowlevel/lowlevel\.h$)");
  return std::regex_search(target, wire);
}

// "file:line includes target" for each include that breaks the rule
template <typename Breaks>
std::string violations(const std::vector<Include>& includes, Breaks breaks) {
  std::string text;
  for (const Include& i : includes) {
    if (breaks(i)) text += "  " + i.file + ":" + std::to_string(i.line) + " includes " + i.target + "\n";
  }
  return text;
}

TEST(IncludeRules, TheScanSeesTheProjectsIncludes) {
  const std::vector<Include> includes = project_includes();
  EXPECT_GT(includes.size(), 200u);
  EXPECT_FALSE(violations(includes, [](const Include& i) { return in_folder(i.target, "core"); }).empty());
}

TEST(IncludeRules, NothingOutsideAppIncludesApp) {
  EXPECT_EQ(violations(project_includes(),
                       [](const Include& i) { return !in_folder(i.file, "app") && in_folder(i.target, "app"); }),
            "");
}

TEST(IncludeRules, ControlEstimationAndSafetyIncludeNeitherIoNorBackend) {
  EXPECT_EQ(violations(project_includes(),
                       [](const Include& i) {
                         const bool inner = in_folder(i.file, "control") || in_folder(i.file, "estimation") ||
                                            in_folder(i.file, "safety");
                         return inner && (in_folder(i.target, "io") || in_folder(i.target, "backend"));
                       }),
            "");
}

TEST(IncludeRules, ModesAndControllersHoldNoEstimatorAndNoTransport) {
  EXPECT_EQ(violations(project_includes(),
                       [](const Include& i) {
                         const bool stage = in_folder(i.file, "modes") || in_folder(i.file, "control");
                         return stage && (in_folder(i.target, "estimation") || in_folder(i.target, "io") ||
                                          in_folder(i.target, "backend") || in_folder(i.target, "viz"));
                       }),
            "");
}

TEST(IncludeRules, CoreIncludesOnlyCore) {
  EXPECT_EQ(violations(project_includes(),
                       [](const Include& i) {
                         return in_folder(i.file, "core") && i.target.find('/') != std::string::npos &&
                                !in_folder(i.target, "core");
                       }),
            "");
}

TEST(IncludeRules, VendorWireTypesStayInIoAppAndTheSdk) {
  EXPECT_EQ(violations(project_includes(),
                       [](const Include& i) {
                         return is_wire_type(i.target) && !in_folder(i.file, "io") && !in_folder(i.file, "app");
                       }),
            "");
}

}  // namespace
}  // namespace cerebellum
