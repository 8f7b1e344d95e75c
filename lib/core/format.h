// Small text formatting helpers for describe() lines.
#pragma once
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

}  // namespace aliaslab
