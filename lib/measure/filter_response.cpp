#include "measure/filter_response.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace aliaslab {

std::string filterResponseCsvHeader() { return "filter,radius,describe,kind,x,value\n"; }

void writeFilterResponseCsv(std::ostream& os, const Filter& f, const FilterResponseGrid& p) {
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

}  // namespace aliaslab
