// read_text_file: the whole text of a file within its limit; an oversized, missing or unreadable
// file is refused with the reason, before an oversized one is read.
#include "core/text_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace cerebellum {
namespace {

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

TEST(TextFile, AFileWithinTheLimitIsReadWholeBytesAsTheyAre) {
  const std::string text = std::string("line one\r\nline two\0three", 24) + "\n";
  const std::string path = write_file("cerebellum_text_file_ok.txt", text);
  std::string error;
  const auto read = read_text_file(path, text.size(), error);
  ASSERT_TRUE(read.has_value()) << error;
  EXPECT_EQ(*read, text);
}

TEST(TextFile, AFileOverTheLimitIsRefusedNamingItsSizeAndTheLimit) {
  const std::string path = write_file("cerebellum_text_file_big.txt", std::string(101, 'x'));
  std::string error;
  EXPECT_FALSE(read_text_file(path, 100, error).has_value());
  EXPECT_EQ(error, "is 101 bytes, more than the limit of 100");
}

TEST(TextFile, AMissingFileIsRefusedAsUnreadable) {
  std::string error;
  EXPECT_FALSE(read_text_file("/nonexistent/cerebellum/file.toml", 100, error).has_value());
  EXPECT_EQ(error.rfind("cannot be read: ", 0), 0u) << error;
}

TEST(TextFile, AFolderIsNotReadAsAFile) {
  std::string error;
  EXPECT_FALSE(read_text_file(std::filesystem::temp_directory_path().string(), 1 << 20, error).has_value());
  EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace cerebellum
