// makeFilter: one explicit if-chain over the names, parameter checking.
#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/format.h"
#include "filter/filter.h"
#include "filter/filter_impl.h"

namespace aliaslab {

namespace {
constexpr float kMinFilterRadius = 1e-3f, kMaxFilterRadius = 1024.f;
}  // namespace

namespace filterimpl {
void requireRange(const std::string& filter, const std::string& param, double value, double lo, double hi) {
  if (!(value >= lo && value <= hi))
    throw OptionError("--filter-param", filter + " " + param + " must be in [" + std::to_string(lo) + ", " +
                                            std::to_string(hi) + "], got " + std::to_string(value));
}
}  // namespace filterimpl

const std::vector<std::string>& filterNames() {
  static const std::vector<std::string> names = {"box",     "tent", "gaussian", "mitchell", "catmullrom",
                                                 "lanczos", "hann", "blackmanharris"};
  return names;
}

FilterParams defaultFilterParams(const std::string& name) {
  if (name == "gaussian") return {{"sigma", 0.5}, {"subtract_edge", 0}};
  if (name == "mitchell") return {{"B", 1.0 / 3.0}, {"C", 1.0 / 3.0}};
  if (name == "lanczos" || name == "hann") return {{"tau", 3}};
  return {};
}

std::unique_ptr<Filter> makeFilter(const std::string& name, float radius, const FilterParams& params) {
  using namespace filterimpl;
  const auto& names = filterNames();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    throw OptionError("--filter", "unknown filter '" + name + "' (valid: " + list + ")");
  }
  if (!std::isfinite(radius) || radius <= 0)
    throw OptionError("--radius", "filter radius must be finite and > 0, got " + formatNumber(radius));
  // Below kMinFilterRadius squared offsets underflow in float; above kMaxFilterRadius
  // the importance weight (the integral of |f|) overflows.
  if (radius < kMinFilterRadius || radius > kMaxFilterRadius)
    throw OptionError("--radius", "filter radius must be in [" + formatNumber(kMinFilterRadius) + ", " +
                                      formatNumber(kMaxFilterRadius) + "] pixels, got " + formatNumber(radius));

  // merge the given shape parameters over the defaults; unknown names fail
  FilterParams p = defaultFilterParams(name);
  for (const auto& [key, value] : params) {
    if (!p.count(key)) {
      std::string valid;
      for (const auto& [k, v] : p) valid += (valid.empty() ? "" : ", ") + k;
      throw OptionError("--filter-param", "'" + key + "' is not a parameter of " + name +
                                              " (valid: " + (valid.empty() ? "none" : valid) + ")");
    }
    if (!std::isfinite(value))
      throw OptionError("--filter-param", name + " " + key + " must be finite, got " + std::to_string(value));
    p[key] = value;
  }

  std::unique_ptr<Filter> f;
  if (name == "box") f = makeBox(radius, p);
  else if (name == "tent") f = makeTent(radius, p);
  else if (name == "gaussian") f = makeGaussian(radius, p);
  else if (name == "mitchell") f = makeMitchell(radius, p);
  else if (name == "catmullrom") f = makeCatmullRom(radius, p);
  else if (name == "lanczos") f = makeLanczos(radius, p);
  else if (name == "hann") f = makeHann(radius, p);
  else f = makeBlackmanHarris(radius, p);
  f->prepare();
  return f;
}

}  // namespace aliaslab
