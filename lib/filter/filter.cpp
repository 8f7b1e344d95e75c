// The Filter base: description, the integral of |f| and the importance-sampling table.
#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "filter/filter.h"
#include "filter/filter_impl.h"
#include "core/format.h"

namespace aliaslab {

/// Piecewise-constant distribution of |f|: along [-r, r] per axis for
/// separable filters (f = g(x) g(y), so |f| factorises), along the radius
/// [0, r] (mass 2 pi rho |g(rho)|) for radial ones.
struct FilterTable {
  bool radial = false;
  double lo = 0, cell = 0;      ///< first cell start and cell width
  std::vector<double> cdf;      ///< cells + 1 cumulative masses, cdf[0] = 0
  double absIntegral = 0;
};

namespace {

constexpr int kSeparableCells = 2048;  // over [-r, r]: width r / 1024
constexpr int kRadialCells = 1024;     // over [0, r]: width r / 1024


/// Cell index c with cdf[c] <= t < cdf[c+1] (skips empty cells), and the position in it in [0, 1).
int findCell(const std::vector<double>& cdf, double t, double& within) {
  const int cells = static_cast<int>(cdf.size()) - 1;
  int c = static_cast<int>(std::upper_bound(cdf.begin(), cdf.end(), t) - cdf.begin()) - 1;
  c = std::clamp(c, 0, cells - 1);
  while (c > 0 && cdf[c + 1] <= cdf[c]) --c;  // t at the very top: last non-empty cell
  const double mass = cdf[c + 1] - cdf[c];
  within = mass > 0 ? std::clamp((t - cdf[c]) / mass, 0.0, 1.0 - 1e-12) : 0.5;
  return c;
}

}  // namespace

Filter::~Filter() = default;

double Filter::absIntegral() const {
  if (!table_) throw std::logic_error("Filter::absIntegral: " + name() + " was not made by makeFilter");
  return table_->absIntegral;
}

void Filter::evalGrid(const float* dx, int nx, const float* dy, int ny, float* out) const {
  for (int b = 0; b < ny; ++b)
    for (int a = 0; a < nx; ++a) out[static_cast<size_t>(b) * nx + a] = eval(dx[a], dy[b]);
}

void Filter::evalBatch(int count, const float* x, const float* y, const float* cx, const float* cy, int n,
                       float* out) const {
  const int stride = batchStride(count);
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a)
      for (int s = 0; s < stride; ++s)
        out[static_cast<size_t>(b * n + a) * stride + s] = eval(x[s] - (cx[s] + a), y[s] - (cy[s] + b));
}

std::string Filter::describe() const {
  std::string s = name() + " r=" + formatNumber(radius(), "%.4g");
  for (const auto& [key, value] : params()) s += " " + key + "=" + formatNumber(value, "%.4g");
  return s;
}

void Filter::prepare() {
  auto table = std::make_shared<FilterTable>();
  const double r = radius();
  table->radial = radial();
  const int cells = table->radial ? kRadialCells : kSeparableCells;
  table->lo = table->radial ? 0.0 : -r;
  table->cell = (table->radial ? r : 2 * r) / cells;
  table->cdf.assign(cells + 1, 0.0);
  for (int c = 0; c < cells; ++c) {
    const double a = table->lo + c * table->cell, b = a + table->cell;
    const double mass = table->radial
        ? filterimpl::integrate([&](double x) { return 2 * M_PI * x * std::abs(profile(float(x))); }, a, b, 1)
        : filterimpl::integrate([&](double x) { return std::abs(profile(float(x))); }, a, b, 1);
    table->cdf[c + 1] = table->cdf[c] + mass;
  }
  const double total = table->cdf.back();
  table->absIntegral = table->radial ? total : total * total;
  table_ = std::move(table);
}

Vec2 Filter::sample(const Vec2& u, float& weight) const {
  if (!table_) throw std::logic_error("Filter::sample: " + name() + " was not made by makeFilter");
  const FilterTable& t = *table_;
  const double total = t.cdf.back();
  Vec2 offset;
  double within;
  if (t.radial) {
    // radius: uniform in area within the cell; angle uniform
    const int c = findCell(t.cdf, u.x() * total, within);
    const double r0 = c * t.cell, r1 = r0 + t.cell;
    const double rho = std::sqrt(r0 * r0 + within * (r1 * r1 - r0 * r0));
    const double phi = 2 * M_PI * u.y();
    offset = Vec2(float(rho * std::cos(phi)), float(rho * std::sin(phi)));
  } else {
    for (int axis = 0; axis < 2; ++axis) {
      const int c = findCell(t.cdf, u[axis] * total, within);
      offset[axis] = float(t.lo + (c + within) * t.cell);
    }
  }
  const float r = radius();
  offset = offset.cwiseMax(-r).cwiseMin(r);
  weight = static_cast<float>(eval(offset.x(), offset.y()) < 0 ? -t.absIntegral : t.absIntegral);
  return offset;
}

}  // namespace aliaslab
