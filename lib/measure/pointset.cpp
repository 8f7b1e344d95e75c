#include "measure/pointset.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace aliaslab {

namespace {

/// A double-double number hi + lo (|lo| <= ulp(hi) / 2): about 106 bits, so
/// the sums of Warnock's formula keep their digits through the final
/// cancellation 1/9 - ... (D^2 is ~1e-6 at N = 1024, the terms ~0.1).
/// Error-free transformations: twoSum (Knuth) and twoProd (fma).
struct DD {
  double hi = 0, lo = 0;
};
DD twoSum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
DD twoProd(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}
DD add(DD a, DD b) {
  DD s = twoSum(a.hi, b.hi);
  s.lo += a.lo + b.lo;
  return twoSum(s.hi, s.lo);
}
DD mul(DD a, DD b) {
  DD p = twoProd(a.hi, b.hi);
  p.lo += a.hi * b.lo + a.lo * b.hi;
  return twoSum(p.hi, p.lo);
}
DD div(DD a, double b) {  // a / b: one correction step of the quotient
  const double q1 = a.hi / b;
  const DD r = add(a, DD{-twoProd(q1, b).hi, -twoProd(q1, b).lo});
  const double q2 = r.hi / b;
  return twoSum(q1, q2);
}
/// 1 - v, exact (v in [0, 1] is a double).
DD oneMinus(double v) { return twoSum(1.0, -v); }

}  // namespace

double l2StarDiscrepancySquared(const std::vector<Vec2>& points) {
  const size_t n = points.size();
  if (n == 0) return 0.0;
  // Warnock's closed form; every term and sum in double-double (see DD), so
  // the result agrees with exact arithmetic to ~1e-15 relative even where
  // the three terms cancel to a millionth of 1/9.
  DD single, pairs;
  for (size_t i = 0; i < n; ++i) {
    const double xi = points[i].x(), yi = points[i].y();
    const DD x2 = twoProd(xi, xi), y2 = twoProd(yi, yi);
    single = add(single, mul(add(DD{1.0, 0.0}, DD{-x2.hi, -x2.lo}), add(DD{1.0, 0.0}, DD{-y2.hi, -y2.lo})));
    pairs = add(pairs, mul(oneMinus(xi), oneMinus(yi)));  // the diagonal term i == j
    DD row;  // sum over j > i, doubled below
    for (size_t j = i + 1; j < n; ++j) {
      const double mx = std::max<double>(xi, points[j].x()), my = std::max<double>(yi, points[j].y());
      row = add(row, mul(oneMinus(mx), oneMinus(my)));
    }
    pairs = add(pairs, DD{2 * row.hi, 2 * row.lo});
  }
  const double dn = static_cast<double>(n);
  // 1/9 - (2 / 4n) single + pairs / n^2
  const DD ninth = div(DD{1.0, 0.0}, 9.0);
  const DD a = div(single, 2 * dn), b = div(div(pairs, dn), dn);
  const DD d2 = add(add(ninth, DD{-a.hi, -a.lo}), b);
  return std::max(0.0, d2.hi + d2.lo);
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
