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

/// A number as printf's %g (6 significant digits): "0.001", "1024", "2e+20".
inline std::string formatNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace aliaslab
