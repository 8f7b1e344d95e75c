// A test program's scratch folder: <temp>/<prefix>_<pid>, made empty on first
// use and removed when the program ends without a failed test (a failed run
// keeps it for a look).
#pragma once
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace aliaslab::testing {

inline const std::filesystem::path& scratchDir(const std::string& prefix) {
  struct Dir {
    std::filesystem::path path;
    ~Dir() {
      if (!::testing::UnitTest::GetInstance()->Failed()) {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
      }
    }
  };
  static const Dir dir = [&] {
    Dir d{std::filesystem::temp_directory_path() / (prefix + "_" + std::to_string(::getpid()))};
    std::filesystem::remove_all(d.path);
    std::filesystem::create_directories(d.path);
    return d;
  }();
  return dir.path;
}

}  // namespace aliaslab::testing
