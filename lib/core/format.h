// Small text formatting helpers for describe() lines, and reading a number back.
#pragma once
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include <Eigen/Core>

namespace aliaslab {

/// "(x y z)" with up to 4 significant digits.
template <class Derived>
std::string formatVector(const Eigen::DenseBase<Derived>& v) {
  std::ostringstream out;
  out << v.transpose().format(Eigen::IOFormat(4, Eigen::DontAlignCols, " ", " ", "", "", "(", ")"));
  return out.str();
}

/// A number in a printf format for one double, by default %g (6 significant
/// digits): "0.001", "1024", "2e+20".
inline std::string formatNumber(double v, const char* format = "%g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

/// A real as the library's records write it (study and spectrum CSVs, reference manifests, convergence tables):
/// %.9g, 9 significant digits, so that a float, and every radius or motion a CSV is keyed by, reads back as written.
inline std::string formatReal(double v) { return formatNumber(v, "%.9g"); }

/// The whole of `text` read as a finite number (std::stod, nothing left over), else NaN.
inline double parseFiniteNumber(const std::string& text) {
  try {
    size_t used = 0;
    const double v = std::stod(text, &used);
    return used == text.size() && std::isfinite(v) ? v : NAN;
  } catch (const std::exception&) {
    return NAN;
  }
}

}  // namespace aliaslab
