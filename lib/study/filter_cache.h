// The study's filters, each built once: the one place lib/study makes a Filter.
//
// A study names a filter by (factory name, radius): its FilterSpec, the key of the CSV's filter and radius columns
// and of the reference manifests. The FilterCache owned by the study plan (study/validate.h StudyPlan) turns each
// spec into one immutable Filter, shared by the rows that reconstruct with it, the targets and the pixel-area
// reference; the references (study/reference/reference.h) take those StudyFilters, so a radius is parsed once and the filter
// a reference splats is the very object whose describe() keys its cache entry.
//
// Errors: get() passes on the factory's OptionError ("filter", "radius"); callers re-key it to their list.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "filter/filter.h"

namespace aliaslab {

using FilterSpec = std::pair<std::string, double>;  ///< (filter name, radius in pixels): the CSV's key

/// The (filter, radius) of the pixel-area reference (box, r = 0.5).
inline const FilterSpec kAreaSpec{"box", 0.5};

/// A (filter, radius) of the study with its filter built once (a Filter is immutable, so it is shared).
struct StudyFilter {
  FilterSpec spec;                       ///< what the CSV and the manifests write
  std::shared_ptr<const Filter> filter;  ///< makeFilter(spec), built by a FilterCache
};

class FilterCache {
 public:
  /// The filter of `spec`, made on its first request and the same object ever after.
  StudyFilter get(const FilterSpec& spec);
  /// get() of each, in order.
  std::vector<StudyFilter> get(const std::vector<FilterSpec>& specs);

 private:
  std::map<FilterSpec, std::shared_ptr<const Filter>> built_;
};

/// Appends `f` to `list` unless a filter of the same spec is there already.
void addFilterOnce(std::vector<StudyFilter>& list, const StudyFilter& f);

}  // namespace aliaslab
