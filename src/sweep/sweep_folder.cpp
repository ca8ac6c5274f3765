#include "sweep/sweep_folder.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/text_file.hpp"
#include "sweep/scenario_file.hpp"

namespace cerebellum {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kRowMaxBytes = 64 * 1024;

std::optional<std::string> read_small(const std::string& path, std::size_t max_bytes) {
  std::string error;
  if (!fs::exists(path)) return std::nullopt;
  return read_text_file(path, max_bytes, error);
}

// whole or not at all: a reader (a rerun, --status, another node) never sees half a file
void write_whole(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + temporary);
  }
  fs::rename(temporary, path);
}

}  // namespace

void SweepFolder::prepare(const std::string& scenario_text, const std::string& scenario_path) const {
  std::error_code error;
  fs::create_directories(fs::path(dir_) / "cells", error);
  if (error) throw std::runtime_error("cannot create the output folder " + dir_ + ": " + error.message());
  const std::string kept = (fs::path(dir_) / "scenario.yaml").string();
  if (const auto previous = read_small(kept, kScenarioMaxBytes)) {
    if (*previous != scenario_text)
      throw std::runtime_error("the output folder " + dir_ + " holds a sweep of another scenario (" + kept +
                               " differs from " + scenario_path +
                               "); give another --out, or remove the folder to start again");
    return;
  }
  write_whole((fs::path(dir_) / "source").string(), fs::absolute(scenario_path).lexically_normal().string() + "\n");
  write_whole(kept, scenario_text);
}

std::string SweepFolder::scenario_text() const {
  const auto text = read_small((fs::path(dir_) / "scenario.yaml").string(), kScenarioMaxBytes);
  if (!text) throw std::runtime_error(dir_ + " holds no sweep (no scenario.yaml)");
  return *text;
}

std::string SweepFolder::scenario_path() const {
  auto text = read_small((fs::path(dir_) / "source").string(), 4096);
  if (!text) throw std::runtime_error(dir_ + " holds no sweep (no source)");
  while (!text->empty() && text->back() == '\n') text->pop_back();
  return *text;
}

std::string SweepFolder::cell_path(std::uint64_t cell, const char* extension) const {
  return (fs::path(dir_) / "cells" / (std::to_string(cell) + extension)).string();
}

std::string SweepFolder::log_path(std::uint64_t cell) const { return cell_path(cell, ".log"); }

bool SweepFolder::finished(std::uint64_t cell) const { return fs::exists(cell_path(cell, ".csv")); }

std::optional<std::string> SweepFolder::row(std::uint64_t cell) const {
  const auto text = read_small(cell_path(cell, ".csv"), kRowMaxBytes);
  if (!text) return std::nullopt;
  // header, then the row
  std::istringstream in(*text);
  std::string header, row;
  if (!std::getline(in, header) || !std::getline(in, row) || row.empty()) return std::nullopt;
  return row;
}

void SweepFolder::write_result(std::uint64_t cell, const std::string& header, const std::string& row) const {
  write_whole(cell_path(cell, ".csv"), header + "\n" + row + "\n");
  std::error_code ignored;
  fs::remove(cell_path(cell, ".crashed"), ignored);
}

void SweepFolder::mark_crashed(std::uint64_t cell, const std::string& reason) const {
  write_whole(cell_path(cell, ".crashed"), reason + "\n");
}

std::optional<std::string> SweepFolder::crash(std::uint64_t cell) const {
  auto text = read_small(cell_path(cell, ".crashed"), kRowMaxBytes);
  if (text) while (!text->empty() && text->back() == '\n') text->pop_back();
  return text;
}

void SweepFolder::write_file(const std::string& name, const std::string& text) const {
  write_whole((fs::path(dir_) / name).string(), text);
}

}  // namespace cerebellum
