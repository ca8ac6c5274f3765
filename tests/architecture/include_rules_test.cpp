// The include rules of docs/architecture.md, checked on every file under src/ against the page's
// own folder table (so the table and the code cannot disagree): dependencies point inward, and
// vendor wire types stay at the edge.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <utility>
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

// the "may include" column of docs/architecture.md's folder table: folder -> folders it may include
// ("everything above": every folder of the rows above; "everything": all; parenthesised notes
// and words that name no folder are ignored)
std::vector<std::pair<std::string, std::set<std::string>>> architecture_table() {
  std::ifstream in(fs::path(CEREBELLUM_SOURCE_DIR) / "docs" / "architecture.md");
  const std::regex row(R"re(^\| `([a-z_]+)/` \|.*\| ([^|]*) \|$)re");
  std::vector<std::pair<std::string, std::string>> cells;
  for (std::string line; std::getline(in, line);) {
    std::smatch match;
    if (std::regex_match(line, match, row)) cells.emplace_back(match[1].str(), match[2].str());
  }
  std::set<std::string> folders;
  for (const auto& [folder, cell] : cells) folders.insert(folder);
  std::vector<std::pair<std::string, std::set<std::string>>> table;
  std::set<std::string> above;
  for (const auto& [folder, cell] : cells) {
    const std::string text = std::regex_replace(cell, std::regex(R"(\([^)]*\))"), "");
    std::set<std::string> allowed;
    if (text.rfind("everything above", 0) == 0) {
      allowed = above;
    } else if (text.rfind("everything", 0) == 0) {
      allowed = folders;
    } else {
      const std::regex word("[a-z_]+");
      for (auto it = std::sregex_iterator(text.begin(), text.end(), word); it != std::sregex_iterator(); ++it) {
        if (folders.count(it->str())) allowed.insert(it->str());
      }
    }
    allowed.insert(folder);
    table.emplace_back(folder, allowed);
    above.insert(folder);
  }
  return table;
}

TEST(IncludeRules, TheArchitectureTableNamesEveryFolderOfSrc) {
  std::set<std::string> in_table;
  for (const auto& [folder, allowed] : architecture_table()) in_table.insert(folder);
  std::string missing;
  for (const fs::directory_entry& entry : fs::directory_iterator(fs::path(CEREBELLUM_SOURCE_DIR) / "src")) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && !in_table.count(name)) missing += " " + name;
  }
  EXPECT_EQ(missing, "") << "folders of src/ without a row in docs/architecture.md";
  EXPECT_GE(in_table.size(), 14u);
}

TEST(IncludeRules, EveryFolderIncludesOnlyWhatItsRowInTheArchitectureTableAllows) {
  const auto table = architecture_table();
  std::set<std::string> folders;
  for (const auto& [folder, allowed] : table) folders.insert(folder);
  EXPECT_EQ(violations(project_includes(),
                       [&](const Include& i) {
                         const std::string target_folder = i.target.substr(0, i.target.find('/'));
                         const std::string file_folder = i.file.substr(0, i.file.find('/'));
                         if (i.target.find('/') == std::string::npos || !folders.count(target_folder)) return false;
                         for (const auto& [folder, allowed] : table) {
                           if (folder == file_folder) return !allowed.count(target_folder);
                         }
                         return true;  // a folder without a row
                       }),
            "");
}

// the hand-over headers the page names: "`io/` may include from `modes/` only these: ..."
std::set<std::string> io_hand_over_headers() {
  std::ifstream in(fs::path(CEREBELLUM_SOURCE_DIR) / "docs" / "architecture.md");
  std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string marker = "may include from `modes/` only these:";
  const std::size_t start = page.find(marker);
  std::set<std::string> headers;
  if (start == std::string::npos) return headers;
  const std::string sentence = page.substr(start, page.find(';', start) - start);
  const std::regex header("`(modes/[a-z_]+\\.hpp)`");
  for (auto it = std::sregex_iterator(sentence.begin(), sentence.end(), header); it != std::sregex_iterator(); ++it) {
    headers.insert((*it)[1].str());
  }
  return headers;
}

TEST(IncludeRules, AnAdapterReachesTheModesOnlyThroughTheHandOverHeaders) {
  const std::set<std::string> allowed = io_hand_over_headers();
  ASSERT_GE(allowed.size(), 2u) << "docs/architecture.md names the hand-over headers";
  for (const std::string& header : allowed) {
    EXPECT_TRUE(fs::exists(fs::path(CEREBELLUM_SOURCE_DIR) / "src" / header)) << header;
  }
  EXPECT_EQ(violations(project_includes(),
                       [&](const Include& i) {
                         return in_folder(i.file, "io") && in_folder(i.target, "modes") && !allowed.count(i.target);
                       }),
            "");
}

TEST(IncludeRules, VendorWireTypesStayInIoAndTheCommandLine) {
  EXPECT_EQ(violations(project_includes(),
                       [](const Include& i) {
                         return is_wire_type(i.target) && !in_folder(i.file, "io") && !in_folder(i.file, "cli");
                       }),
            "");
}

}  // namespace
}  // namespace cerebellum
