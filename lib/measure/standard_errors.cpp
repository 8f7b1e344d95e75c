#include "measure/standard_errors.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace aliaslab {

double jackknifeSe(const std::vector<double>& leaveOneOut) {
  const double k = static_cast<double>(leaveOneOut.size());
  double mean = 0;
  for (double v : leaveOneOut) mean += v / k;
  double ss = 0;
  for (double v : leaveOneOut) ss += (v - mean) * (v - mean);
  return std::sqrt((k - 1) / k * ss);
}

// Two estimates of Var(U):
// - unbiased (Hoeffding): Var(U) = E[U^2] - theta^2 and theta^2 = E[h(k, l) h(i, j)] for four distinct seeds, so
//   V = U^2 - (mean over pairs of disjoint pairs of h(k, l) h(i, j)), the disjoint sum being S^2 + Q - sum_j R_j^2
//   (S = sum of h over pairs, Q = sum of h^2, R_j = sum over l != j of h(j, l)). It can come out negative.
// - the leave-one-seed-out jackknife V_J, never negative, whose expectation lies between Var(U) and
//   2 (K-1) / (K-2) Var(U) (the upper end when the pair terms share no per-seed part, e.g. zero aliasing).
// The result is sqrt(max(V, V_J (K-2) / (2 (K-1)))): the unbiased value, floored by the jackknife scaled to a
// lower bound in expectation, so a chance negative V does not claim a zero error. h is centred on U first
// (V does not change) so no large terms cancel.
double pairStatisticSe(const std::vector<std::vector<double>>& h) {
  const int K = static_cast<int>(h.size());
  if (K < 4) return std::numeric_limits<double>::quiet_NaN();
  const double pairs = K * (K - 1) / 2.0;
  double u = 0;
  for (int a = 0; a < K; ++a)
    for (int b = 0; b < a; ++b) u += h[a][b] / pairs;
  double s = 0, q = 0, r2 = 0;
  std::vector<double> r(K, 0.0);
  for (int a = 0; a < K; ++a)
    for (int b = 0; b < a; ++b) {
      const double c = h[a][b] - u;
      s += c, q += c * c, r[a] += c, r[b] += c;
    }
  for (double v : r) r2 += v * v;
  const double disjoint = (s * s + q - r2) / (pairs * (K - 2) * (K - 3) / 2.0);
  const double mean = s / pairs;  // 0 up to rounding
  const double unbiased = mean * mean - disjoint;
  std::vector<double> leaveOneOut(K);
  for (int j = 0; j < K; ++j) leaveOneOut[j] = (s - r[j]) / (pairs - (K - 1));
  const double jack = jackknifeSe(leaveOneOut);
  return std::sqrt(std::max(unbiased, jack * jack * (K - 2) / (2.0 * (K - 1))));
}

int correlationLag(double radius) { return std::max(0, static_cast<int>(std::ceil(2 * radius)) - 1); }

double windowSumVariance(const std::vector<double>& x, int width, int height, int lag) {
  // per-pixel sums s_p, then a summed-area table of s for the window sums
  const size_t w1 = static_cast<size_t>(width) + 1;
  // (this thread's buffers, reused call after call: every value of s and every inner value of the table is
  // written before it is read; the table's first row and column, which are read and never written, are zeroed)
  thread_local std::vector<double> s, table;
  s.resize(static_cast<size_t>(width) * height), table.resize(w1 * (height + 1));
  std::fill(table.begin(), table.begin() + static_cast<std::ptrdiff_t>(w1), 0.0);
  for (int y = 1; y <= height; ++y) table[y * w1] = 0.0;
  for (size_t p = 0; p < s.size(); ++p) s[p] = x[3 * p] + x[3 * p + 1] + x[3 * p + 2];
  for (int y = 0; y < height; ++y)
    for (int px = 0; px < width; ++px)
      table[(y + 1) * w1 + px + 1] = s[static_cast<size_t>(y) * width + px] + table[y * w1 + px + 1] +
                                     table[(y + 1) * w1 + px] - table[y * w1 + px];
  double v = 0;
  for (int y = 0; y < height; ++y)
    for (int px = 0; px < width; ++px) {
      const int x0 = std::max(0, px - lag), x1 = std::min(width, px + lag + 1);
      const int y0 = std::max(0, y - lag), y1 = std::min(height, y + lag + 1);
      const double window = table[y1 * w1 + x1] - table[y0 * w1 + x1] - table[y1 * w1 + x0] + table[y0 * w1 + x0];
      v += s[static_cast<size_t>(y) * width + px] * window;
    }
  return std::max(0.0, v);
}

}  // namespace aliaslab
