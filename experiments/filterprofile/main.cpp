// filterprofile: each filter's 1-D profile and frequency response, as CSV,
// for analysis/aliaslab_analysis/charts/filter_profiles.py (one source of truth: the library's eval).
//
// Columns and the response's definition: lib/measure/filter_response.h.
// Filters are drawn at their natural radius (box 0.5, tent 1, gaussian 1.5 =
// 3 sigma, mitchell and catmullrom 2, lanczos and hann 3, blackmanharris 2).
#include <CLI/CLI.hpp>
#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "common/cli.h"
#include "common/front_end.h"
#include "core/files.h"
#include "core/error.h"
#include "filter/filter.h"
#include "measure/filter_response.h"

using namespace aliaslab;

namespace {

struct Params {
  std::string out;  // CSV file (default: stdout)
  FilterResponseGrid grid;
};

// The library's keys in this program's flags.
const FrontEnd kFilterProfile{"filterprofile", {{"out", "--output"}}};

}  // namespace

int main(int argc, char** argv) {
  Params p;
  CLI::App app{"filterprofile: profile and frequency response of every filter at its natural radius, as CSV (aliaslab)"};
  setupCommandLine(app, "filterprofile");
  app.add_option("--output", p.out, "CSV file (default: standard output)");
  app.add_option("--max-frequency", p.grid.maxFrequency, "Largest frequency, cycles per pixel")
      ->capture_default_str()
      ->check(CLI::Range(0.1, 16.0));
  if (const int rc = parseCommandLine(app, argc, argv, "filterprofile"); rc >= 0) return rc;
  return runFrontEnd(kFilterProfile, [&] {
    if (!p.out.empty()) {  // a file we can write, checked before the work
      namespace fs = std::filesystem;
      std::error_code ec;
      if (fs::is_directory(p.out, ec)) throw OptionError("--output", "'" + p.out + "' is a folder; give a CSV file name");
      const fs::path dir = fs::path(p.out).parent_path().empty() ? fs::path(".") : fs::path(p.out).parent_path();
      if (!fs::is_directory(dir, ec) || ::access(dir.c_str(), W_OK) != 0)
        throw OptionError("--output", "cannot write into folder '" + dir.string() + "'");
    }
    std::ostringstream os;
    os << filterResponseCsvHeader();
    for (const auto& name : filterNames()) writeFilterResponseCsv(os, *makeFilter(name, static_cast<float>(defaultFilterRadius(name))), p.grid);
    if (p.out.empty()) {
      std::cout << os.str();
    } else {
      writeTextFile(p.out, os.str());
    }
    return 0;
  });
}
