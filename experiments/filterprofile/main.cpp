// filterprofile: each filter's 1-D profile and frequency response, as CSV,
// for analysis/filter_profiles.py (one source of truth: the library's eval).
//
// Columns: filter,radius,describe,kind,x,value
//   kind = profile:  x = offset in pixels, value = the 1-D profile g(x)
//     (Filter::profile; f(x, y) = g(x) g(y) for separable filters, g(|d|) for radial)
//   kind = response: x = frequency in cycles per pixel, value = |H(x)|, the
//     2-D filter's normalised Fourier transform along the x axis,
//     H(nu) = int int f(x, y) exp(-2 pi i nu x) dx dy / int int f(x, y) dx dy,
//     computed as the cosine transform of the projection p(x) = int f(x, y) dy
//     (midpoint rule, step r / 256 in x and y). For separable filters this is
//     the 1-D transform of the profile; for radial ones (tent, gaussian) it is
//     the true response of the disc-supported filter, not of its slice.
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

#include "core/cli.h"
#include "core/files.h"
#include "core/error.h"
#include "filter/filter.h"

using namespace aliaslab;

namespace {

struct Params {
  std::string out;            // CSV file (default: stdout)
  double maxFrequency = 2.0;  // cycles per pixel
  int frequencySteps = 400;   // response samples in [0, maxFrequency]
  int profileSteps = 400;     // profile samples across [-r - 0.25, r + 0.25]
};

void writeFilter(std::ostream& os, const Filter& f, const Params& p) {
  const double r = f.radius();
  std::string describe = f.describe();
  std::replace(describe.begin(), describe.end(), ',', ';');
  const std::string head = f.name() + "," + std::to_string(r) + "," + describe + ",";
  char buf[96];
  for (int i = 0; i <= p.profileSteps; ++i) {
    const double x = -r - 0.25 + (2 * r + 0.5) * i / p.profileSteps;
    std::snprintf(buf, sizeof buf, "profile,%.6g,%.9g\n", x, f.profile(static_cast<float>(x)));
    os << head << buf;
  }
  // Projection onto x, then its cosine transform.
  const int cells = 512;
  const double h = 2 * r / cells;
  std::vector<double> xs(cells), proj(cells, 0.0);
  double total = 0;
  for (int a = 0; a < cells; ++a) {
    xs[a] = -r + (a + 0.5) * h;
    for (int b = 0; b < cells; ++b)
      proj[a] += f.eval(static_cast<float>(xs[a]), static_cast<float>(-r + (b + 0.5) * h)) * h;
    total += proj[a] * h;
  }
  for (int i = 0; i <= p.frequencySteps; ++i) {
    const double nu = p.maxFrequency * i / p.frequencySteps;
    double re = 0;
    for (int a = 0; a < cells; ++a) re += proj[a] * std::cos(2 * M_PI * nu * xs[a]) * h;
    std::snprintf(buf, sizeof buf, "response,%.6g,%.9g\n", nu, std::abs(re / total));
    os << head << buf;
  }
}

}  // namespace

int main(int argc, char** argv) {
  Params p;
  CLI::App app{"filterprofile: profile and frequency response of every filter at its natural radius, as CSV (aliaslab)"};
  setupCommandLine(app, "filterprofile");
  app.add_option("--output", p.out, "CSV file (default: standard output)");
  app.add_option("--max-frequency", p.maxFrequency, "Largest frequency, cycles per pixel")
      ->capture_default_str()
      ->check(CLI::Range(0.1, 16.0));
  if (const int rc = parseCommandLine(app, argc, argv, "filterprofile"); rc >= 0) return rc;
  try {
    if (!p.out.empty()) {  // a file we can write, checked before the work
      namespace fs = std::filesystem;
      std::error_code ec;
      if (fs::is_directory(p.out, ec)) throw OptionError("--output", "'" + p.out + "' is a folder; give a CSV file name");
      const fs::path dir = fs::path(p.out).parent_path().empty() ? fs::path(".") : fs::path(p.out).parent_path();
      if (!fs::is_directory(dir, ec) || ::access(dir.c_str(), W_OK) != 0)
        throw OptionError("--output", "cannot write into folder '" + dir.string() + "'");
    }
    std::ostringstream os;
    os << "filter,radius,describe,kind,x,value\n";
    for (const auto& name : filterNames()) writeFilter(os, *makeFilter(name, static_cast<float>(defaultFilterRadius(name))), p);
    if (p.out.empty()) {
      std::cout << os.str();
    } else {
      writeTextFile(p.out, os.str());
    }
  } catch (const InputError& e) {
    std::cerr << "filterprofile: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "filterprofile: failed: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
