// The Filter base: its description.
#include "filter/filter.h"

#include "core/format.h"

namespace aliaslab {

Filter::~Filter() = default;

std::string Filter::describe() const {
  std::string s = name() + " r=" + formatNumber(radius(), "%.4g");
  for (const auto& [key, value] : params()) s += " " + key + "=" + formatNumber(value, "%.4g");
  return s;
}

}  // namespace aliaslab
