// Runs a fuzz target over every file of the folders (or files) given: the seed corpus, in every
// build, as a test. Exit status 0 when every input ran; a failed check aborts.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "fuzz_target.hpp"

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::size_t inputs = 0;
  const auto run = [&inputs](const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    ++inputs;
  };
  for (int i = 1; i < argc; ++i) {
    const fs::path path(argv[i]);
    if (fs::is_directory(path)) {
      for (const auto& entry : fs::directory_iterator(path)) {
        if (entry.is_regular_file()) run(entry.path());
      }
    } else if (fs::is_regular_file(path)) {
      run(path);
    } else {
      std::fprintf(stderr, "replay: no such file or folder: %s\n", argv[i]);
      return 2;
    }
  }
  // the empty input too
  LLVMFuzzerTestOneInput(nullptr, 0);
  std::printf("replayed %zu inputs and the empty one: no check failed\n", inputs);
  return inputs > 0 ? 0 : 1;
}
