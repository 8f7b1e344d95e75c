// Small text formatting helpers for describe() lines.
#pragma once
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

}  // namespace aliaslab
