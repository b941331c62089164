#include "talus/scenario/compare_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "talus/core/error.hpp"
#include "talus/io/toml_reader.hpp"
#include "talus/scenario/scenario.hpp"

namespace talus::io {

CompareFile read_compare_file(const std::string& path) {
  const ScenarioFile file = load_scenario_file(path, {});
  TomlReader root(file.table, path);
  CompareFile c;
  c.path = path;
  if (root.required_string("method") != "compare")
    root.fail("method", "expected \"compare\" in a comparison file (talus compare FILE)");
  c.name = root.string("name", std::filesystem::path(path).stem().string());
  c.description = root.string("description", "");
  TomlReader methods = root.required_table("methods");
  const auto folder = std::filesystem::path(path).parent_path();
  for (const char* method : kCompareMethods) {
    if (auto file_name = methods.optional_string(method)) {
      std::filesystem::path p = *file_name;
      if (p.is_relative()) p = folder / p;
      if (!std::filesystem::exists(p))
        methods.fail(method, fmt::format("scenario file {} does not exist", p.string()));
      c.methods[method] = p.string();
    }
  }
  methods.finish();
  if (c.methods.empty())
    methods.fail("methods",
                 "expected at least one of dem, dan, fv2d, two_phase, mpm = \"scenario.toml\"");
  root.finish();
  return c;
}

}  // namespace talus::io
