// Replays every saved fuzzing finding (tests/fuzz/regressions/<target>/*)
// and every seed (scenes/*.txt, scenes/meshes/*.obj, tests/fuzz/seeds/*)
// through the fuzz entry points themselves (tests/fuzz/fuzz_entry.h): each
// input must end in an InputError or succeed, never crash, throw anything
// else or break a checked promise. One test per input.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <filesystem>

#include "support/run_process.h"

#define ALIASLAB_FUZZ_NO_MAIN
#include "experiments/raytracer/options.cpp"
#include "experiments/raytracer/sampling_plan.cpp"
#include "fuzz/fuzz_cli.cpp"
#include "fuzz/fuzz_obj.cpp"
#include "fuzz/fuzz_scene.cpp"

namespace fs = std::filesystem;

namespace {

struct Input {
  std::string target;  ///< fuzz_scene, fuzz_obj or fuzz_cli
  std::string path;
  std::string label;   ///< test name
};

std::vector<Input> collectInputs() {
  const fs::path src = ALIASLAB_SOURCE_DIR, fuzz = src / "tests/fuzz";
  std::vector<Input> inputs;
  auto add = [&](const std::string& target, const fs::path& dir, const std::string& kind, const std::string& ext) {
    if (!fs::is_directory(dir)) return;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file() && (ext.empty() || e.path().extension() == ext)) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& p : files) {
      std::string label = target + "_" + kind + "_" + p.filename().string();
      for (char& c : label)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      inputs.push_back({target, p.string(), label});
    }
  };
  for (const char* t : {"fuzz_scene", "fuzz_obj", "fuzz_cli"}) add(t, fuzz / "regressions" / t, "regression", "");
  add("fuzz_scene", src / "scenes", "seed", ".txt");
  add("fuzz_obj", src / "scenes/meshes", "seed", ".obj");
  add("fuzz_obj", fuzz / "seeds/obj", "seed", "");
  add("fuzz_cli", fuzz / "seeds/cli", "seed", "");
  return inputs;
}

class FuzzRegression : public ::testing::TestWithParam<Input> {};

TEST_P(FuzzRegression, EndsInInputErrorOrSuccessWithoutCrashing) {
  const Input& in = GetParam();
  const std::string bytes = aliaslab::testing::readText(in.path);
  const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
  if (in.target == "fuzz_scene") EXPECT_NO_THROW(aliaslab::fuzz::fuzzScene(data, bytes.size()));
  else if (in.target == "fuzz_obj") EXPECT_NO_THROW(aliaslab::fuzz::fuzzObj(data, bytes.size()));
  else EXPECT_NO_THROW(aliaslab::fuzz::fuzzCli(data, bytes.size()));
}

INSTANTIATE_TEST_SUITE_P(Inputs, FuzzRegression, ::testing::ValuesIn(collectInputs()),
                         [](const ::testing::TestParamInfo<Input>& info) { return info.param.label; });

}  // namespace
