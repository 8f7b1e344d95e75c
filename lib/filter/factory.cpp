// The one table of filter names (filterNames() order, make and batch functions, shape parameters and their
// defaults, natural radius, course variant) and makeFilter(): name, radius and parameter checks, then the
// filter's make function.
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
    throw OptionError("filter-param", filter + " " + param + " must be in [" + formatNumber(lo) + ", " +
                                            formatNumber(hi) + "], got " + formatNumber(value));
}
}  // namespace filterimpl

namespace {
using Maker = std::unique_ptr<Filter> (*)(float, const FilterParams&);
struct Entry {
  const char* name;
  Maker make;              ///< declared in filter_impl.h, defined in the filter's own file
  filterimpl::BatchMaker batch;  ///< FilterBatch's kernel (filter_batch_impl.h); null: eval() sample by sample
  FilterParams defaults;   ///< every shape parameter the filter takes, with its default
  double (*naturalRadius)(const FilterParams&);  ///< the radius used when none is given (see filter.h)
  const char* course = nullptr;  ///< the name of its course variant (makeCourseVariant), or null: itself
  bool variant = false;  ///< a course variant or gaussian-cut: in allFilterNames(), not in filterNames() (the study's)
};
// Registered filters, in the fixed order of filterNames(): adding a filter is its file, its functions'
// declarations in filter_impl.h and one line here.
const std::vector<Entry>& registry() {
  using namespace filterimpl;
  static const std::vector<Entry> entries = {
      {"box", makeBox, boxBatch, {}, [](const FilterParams&) { return 0.5; }},
      {"tent", makeTent, tentBatch, {}, [](const FilterParams&) { return 1.0; }},
      {"gaussian", makeGaussian, gaussianBatch, {{"sigma", 0}, {"subtract_edge", 0}},
       [](const FilterParams& p) { return p.at("sigma") > 0 ? 3 * p.at("sigma") : 1.5; }, "course-gaussian"},
      {"mitchell", makeMitchell, mitchellBatch, {{"B", 1.0 / 3.0}, {"C", 1.0 / 3.0}},
       [](const FilterParams&) { return 2.0; }},
      {"catmullrom", makeCatmullRom, mitchellBatch, {}, [](const FilterParams&) { return 2.0; }},
      {"lanczos", makeLanczos, lanczosBatch, {{"tau", 3}}, [](const FilterParams& p) { return p.at("tau"); }},
      {"hann", makeHann, hannBatch, {{"tau", 3}}, [](const FilterParams& p) { return p.at("tau"); }},
      {"blackmanharris", makeBlackmanHarris, blackmanHarrisBatch, {}, [](const FilterParams&) { return 2.0; }},
      {"gaussian-cut", makeGaussianCut, gaussianBatch, {{"sigma", 0.5}, {"subtract_edge", 0}},
       [](const FilterParams& p) { return 3 * p.at("sigma"); }, "course-gaussian", true},
      {"course-gaussian", makeCourseGaussian, nullptr, {{"sigma", 0.5}},
       [](const FilterParams& p) { return std::max(0.0, std::ceil(2 * p.at("sigma") - 0.5)) + 0.5; }, nullptr, true},
  };
  return entries;
}
const Entry* find(const std::string& name) {
  for (const Entry& e : registry())
    if (name == e.name) return &e;
  return nullptr;
}
}  // namespace

namespace filterimpl {
BatchMaker batchMaker(const std::string& name) {
  const Entry* e = find(name);
  return e ? e->batch : nullptr;
}
}  // namespace filterimpl

const std::vector<std::string>& filterNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const Entry& e : registry())
      if (!e.variant) v.emplace_back(e.name);
    return v;
  }();
  return names;
}

const std::vector<std::string>& allFilterNames() {
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
    for (const auto& n : allFilterNames()) list += (list.empty() ? "" : ", ") + n;
    throw OptionError("filter", "unknown filter '" + name + "' (valid: " + list + ")");
  }
  if (!std::isfinite(radius) || radius <= 0)
    throw OptionError("radius", "filter radius must be finite and > 0, got " + formatNumber(radius));
  // Below kMinFilterRadius squared offsets underflow in float; above kMaxFilterRadius
  // the importance weight (the integral of |f|) overflows.
  if (radius < kMinFilterRadius || radius > kMaxFilterRadius)
    throw OptionError("radius", "filter radius must be in [" + formatNumber(kMinFilterRadius) + ", " +
                                      formatNumber(kMaxFilterRadius) + "] pixels, got " + formatNumber(radius));

  // merge the given shape parameters over the defaults; unknown names fail
  FilterParams p = entry->defaults;
  for (const auto& [key, value] : params) {
    if (!p.count(key)) {
      std::string valid;
      for (const auto& [k, v] : p) valid += (valid.empty() ? "" : ", ") + k;
      throw OptionError("filter-param", "'" + key + "' is not a parameter of " + name +
                                              " (valid: " + (valid.empty() ? "none" : valid) + ")");
    }
    if (!std::isfinite(value))
      throw OptionError("filter-param", name + " " + key + " must be finite, got " + formatNumber(value));
    p[key] = value;
  }

  return entry->make(radius, p);
}

std::unique_ptr<Filter> makeCourseVariant(const Filter& filter) {
  const Entry* e = find(filter.name());
  if (!e || !e->course) return nullptr;
  FilterParams p = defaultFilterParams(e->course);
  for (auto& [key, value] : p)
    if (const FilterParams given = filter.params(); given.count(key)) value = given.at(key);
  return makeFilter(e->course, static_cast<float>(defaultFilterRadius(e->course, p)), p);
}

}  // namespace aliaslab
