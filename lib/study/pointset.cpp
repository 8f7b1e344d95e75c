#include "study/pointset.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace aliaslab {

double l2StarDiscrepancySquared(const std::vector<Vec2>& points) {
  const size_t n = points.size();
  if (n == 0) return 0.0;
  // Warnock's closed form, in double precision.
  double single = 0.0, pairs = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const double xi = points[i].x(), yi = points[i].y();
    single += (1.0 - xi * xi) * (1.0 - yi * yi) / 4.0;
    pairs += (1.0 - xi) * (1.0 - yi);  // the diagonal term i == j
    for (size_t j = i + 1; j < n; ++j) {
      const double mx = std::max<double>(xi, points[j].x()), my = std::max<double>(yi, points[j].y());
      pairs += 2.0 * (1.0 - mx) * (1.0 - my);
    }
  }
  const double dn = static_cast<double>(n);
  return std::max(0.0, 1.0 / 9.0 - 2.0 * single / dn + pairs / (dn * dn));
}

double l2StarDiscrepancy(const std::vector<Vec2>& points) {
  return std::sqrt(l2StarDiscrepancySquared(points));
}

double minToroidalDistance(const std::vector<Vec2>& points) {
  double best2 = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < points.size(); ++i)
    for (size_t j = i + 1; j < points.size(); ++j) {
      double dx = std::abs(double(points[i].x()) - points[j].x());
      double dy = std::abs(double(points[i].y()) - points[j].y());
      dx = std::min(dx, 1.0 - dx);
      dy = std::min(dy, 1.0 - dy);
      best2 = std::min(best2, dx * dx + dy * dy);
    }
  return std::sqrt(best2);
}

double idealPackingDistance(int n) { return std::sqrt(2.0 / (std::sqrt(3.0) * n)); }

Periodogram::Periodogram(int half) : half_(std::max(1, half)), sum_(static_cast<size_t>(size()) * size(), 0.0) {}

void Periodogram::add(const std::vector<Vec2>& points) {
  // F(kx, ky) = sum_j ex(kx, j) ey(ky, j): one complex matrix product.
  using Mat = Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic>;
  const int m = size(), n = static_cast<int>(points.size());
  Mat ex(m, n), ey(m, n);
  for (int j = 0; j < n; ++j)
    for (int k = -half_; k <= half_; ++k) {
      ex(k + half_, j) = std::polar(1.0, -2.0 * M_PI * k * double(points[j].x()));
      ey(k + half_, j) = std::polar(1.0, -2.0 * M_PI * k * double(points[j].y()));
    }
  const Mat f = ex * ey.transpose();  // f(kx, ky)
  const double inv = n > 0 ? 1.0 / n : 0.0;
  for (int ky = 0; ky < m; ++ky)
    for (int kx = 0; kx < m; ++kx) sum_[static_cast<size_t>(ky) * m + kx] += std::norm(f(kx, ky)) * inv;
  ++sets_;
}

std::vector<double> radialSpectrum(const Periodogram& p) {
  const int h = p.half();
  std::vector<double> sum(h + 1, 0.0);
  std::vector<int> count(h + 1, 0);
  for (int ky = -h; ky <= h; ++ky)
    for (int kx = -h; kx <= h; ++kx) {
      const int r = static_cast<int>(std::floor(std::sqrt(double(kx * kx + ky * ky)) + 0.5));
      if (r > h) continue;
      sum[r] += p.at(kx, ky);
      ++count[r];
    }
  for (int r = 0; r <= h; ++r) sum[r] = count[r] ? sum[r] / count[r] : 0.0;
  return sum;
}

Image plotPointSet(const std::vector<Vec2>& pts, int size) {
  const int pad = 8, inner = size - 2 * pad, r = pts.size() > 256 ? 1 : 2;
  Image img(size, size, Color::Ones());
  // Frame of the unit square.
  for (int i = 0; i <= inner; ++i)
    for (int e : {pad, pad + inner}) {
      img.set(pad + i, e, Color::Constant(0.6f));
      img.set(e, pad + i, Color::Constant(0.6f));
    }
  // A small disc per point.
  for (const Vec2& p : pts) {
    const int cx = pad + static_cast<int>(p.x() * inner), cy = pad + static_cast<int>(p.y() * inner);
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx)
        if (dx * dx + dy * dy <= r * r + 1)
          img.set(std::clamp(cx + dx, 0, size - 1), std::clamp(cy + dy, 0, size - 1), Color::Zero());
  }
  return img;
}

Image plotPeriodogram(const Periodogram& p) {
  const int m = p.size(), scale = std::max(1, 384 / m), h = p.half();
  Image img(m * scale, m * scale);
  for (int ky = -h; ky <= h; ++ky)
    for (int kx = -h; kx <= h; ++kx) {
      const double power = std::max(p.at(kx, ky), 1e-12);
      const double v = (kx == 0 && ky == 0) ? 1.0 : std::clamp(0.5 + 0.25 * std::log2(power), 0.0, 1.0);
      for (int y = 0; y < scale; ++y)
        for (int x = 0; x < scale; ++x)
          img.set((kx + h) * scale + x, (ky + h) * scale + y, Color::Constant(static_cast<float>(v)));
    }
  return img;
}

}  // namespace aliaslab
