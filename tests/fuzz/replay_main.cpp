// Runs the scenario fuzzer's harness (fuzz_scenario.cpp) over files, without
// libFuzzer: make test replays the inputs the fuzzer once found failing
// (tests/fuzz/regressions/) and the bundled scenarios. A finding aborts.
// Args: files or folders (every file in a folder and its sub-folders, sorted).
// A .toml file is read as if at its own path, so that a bundled scenario's
// `extends` and data files resolve as in a run; any other file at the
// harness's default place.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
void fuzz_scenario_place(const std::string& path);

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    if (fs::is_directory(argv[i])) {
      for (const auto& e : fs::recursive_directory_iterator(argv[i]))
        if (e.is_regular_file()) files.push_back(e.path());
    } else {
      files.emplace_back(argv[i]);
    }
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    fuzz_scenario_place(f.extension() == ".toml" ? fs::absolute(f).string() : "");
    std::ifstream in(f, std::ios::binary);
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) {
      std::fprintf(stderr, "cannot read %s\n", f.c_str());
      return 1;
    }
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(data.data()), data.size());
  }
  std::printf("fuzz_replay: %zu inputs read without a finding\n", files.size());
  return files.empty() ? 1 : 0;
}
