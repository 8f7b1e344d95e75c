#include "study/filter_cache.h"

#include <algorithm>

namespace aliaslab {

StudyFilter FilterCache::get(const FilterSpec& spec) {
  auto& f = built_[spec];
  if (!f) f = makeFilter(spec.first, static_cast<float>(spec.second));
  return {spec, f};
}

std::vector<StudyFilter> FilterCache::get(const std::vector<FilterSpec>& specs) {
  std::vector<StudyFilter> out;
  for (const FilterSpec& s : specs) out.push_back(get(s));
  return out;
}

void addFilterOnce(std::vector<StudyFilter>& list, const StudyFilter& f) {
  if (std::none_of(list.begin(), list.end(), [&](const StudyFilter& g) { return g.spec == f.spec; })) list.push_back(f);
}

}  // namespace aliaslab
