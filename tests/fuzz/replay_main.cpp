// SPDX-License-Identifier: MIT
// Runs a fuzz target once over every file of the given corpus directories, without
// libFuzzer: built with the normal toolchain, so ./test replays the committed corpus.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
  std::size_t n_inputs = 0;
  for (int k = 1; k < argc; ++k) {
    if (!std::filesystem::is_directory(argv[k])) {
      std::fprintf(stderr, "replay: %s is not a corpus directory\n", argv[k]);
      return 2;
    }
    for (const auto& entry : std::filesystem::directory_iterator(argv[k])) {
      if (!entry.is_regular_file()) continue;
      std::ifstream stream(entry.path(), std::ios::binary);
      const std::vector<char> bytes((std::istreambuf_iterator<char>(stream)),
                                    std::istreambuf_iterator<char>());
      LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
      ++n_inputs;
    }
  }
  std::printf("replayed %zu inputs\n", n_inputs);
  return n_inputs > 0 ? 0 : 1;
}
