// The one table of filter names (filterNames() order, shape parameters and their defaults) and
// makeFilter(): name, radius and parameter checks, then the filter's make function.
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
    throw OptionError("--filter-param", filter + " " + param + " must be in [" + formatNumber(lo) + ", " +
                                            formatNumber(hi) + "], got " + formatNumber(value));
}
}  // namespace filterimpl

namespace {
using Maker = std::unique_ptr<Filter> (*)(float, const FilterParams&);
struct Entry {
  const char* name;
  Maker make;        ///< declared in filter_impl.h, defined in the filter's own file
  FilterParams defaults;  ///< every shape parameter the filter takes, with its default
  double (*naturalRadius)(const FilterParams&);  ///< the radius used when none is given (see filter.h)
};
// Registered filters, in the fixed order of filterNames(): adding a filter is its file, its make function's
// declaration in filter_impl.h and one line here.
const std::vector<Entry>& registry() {
  using namespace filterimpl;
  static const std::vector<Entry> entries = {
      {"box", makeBox, {}, [](const FilterParams&) { return 0.5; }},
      {"tent", makeTent, {}, [](const FilterParams&) { return 1.0; }},
      {"gaussian", makeGaussian, {{"sigma", 0.5}, {"subtract_edge", 0}},
       [](const FilterParams& p) { return 3 * p.at("sigma"); }},
      {"mitchell", makeMitchell, {{"B", 1.0 / 3.0}, {"C", 1.0 / 3.0}}, [](const FilterParams&) { return 2.0; }},
      {"catmullrom", makeCatmullRom, {}, [](const FilterParams&) { return 2.0; }},
      {"lanczos", makeLanczos, {{"tau", 3}}, [](const FilterParams& p) { return p.at("tau"); }},
      {"hann", makeHann, {{"tau", 3}}, [](const FilterParams& p) { return p.at("tau"); }},
      {"blackmanharris", makeBlackmanHarris, {}, [](const FilterParams&) { return 2.0; }},
  };
  return entries;
}
const Entry* find(const std::string& name) {
  for (const Entry& e : registry())
    if (name == e.name) return &e;
  return nullptr;
}
}  // namespace

const std::vector<std::string>& filterNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const Entry& e : registry()) v.emplace_back(e.name);
    return v;
  }();
  return names;
}

FilterParams defaultFilterParams(const std::string& name) {
  const Entry* e = find(name);
  return e ? e->defaults : FilterParams{};
}

double defaultFilterRadius(const std::string& name, const FilterParams& params) {
  const Entry* e = find(name);
  if (!e) return 1.0;  // makeFilter reports the unknown name
  FilterParams p = e->defaults;
  for (const auto& [key, value] : params)
    if (p.count(key)) p[key] = value;
  return std::clamp(e->naturalRadius(p), double(kMinFilterRadius), double(kMaxFilterRadius));
}

std::unique_ptr<Filter> makeFilter(const std::string& name, float radius, const FilterParams& params) {
  const Entry* entry = find(name);
  if (!entry) {
    std::string list;
    for (const auto& n : filterNames()) list += (list.empty() ? "" : ", ") + n;
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
  FilterParams p = entry->defaults;
  for (const auto& [key, value] : params) {
    if (!p.count(key)) {
      std::string valid;
      for (const auto& [k, v] : p) valid += (valid.empty() ? "" : ", ") + k;
      throw OptionError("--filter-param", "'" + key + "' is not a parameter of " + name +
                                              " (valid: " + (valid.empty() ? "none" : valid) + ")");
    }
    if (!std::isfinite(value))
      throw OptionError("--filter-param", name + " " + key + " must be finite, got " + formatNumber(value));
    p[key] = value;
  }

  std::unique_ptr<Filter> f = entry->make(radius, p);
  f->prepare();
  return f;
}

}  // namespace aliaslab
