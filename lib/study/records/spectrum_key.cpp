#include "study/records/spectrum_key.h"

#include "study/records/csv.h"

namespace aliaslab {

const std::vector<std::string>& spectrumKeyColumns() {
  static const std::vector<std::string> columns = {"scene",  "sampler",        "spp",      "filter",
                                                   "radius", "reconstruction", "prefilter"};
  return columns;
}

std::string spectrumKeyOf(const std::vector<std::string>& fields, const std::vector<size_t>& at) {
  std::string key;
  for (size_t c : at) key += (key.empty() ? "" : ",") + fields.at(c);
  return key;
}

std::string spectrumKeyOfCsvRow(const std::vector<std::string>& f) {
  static const std::vector<size_t> at = [] {
    std::vector<size_t> v;
    for (const std::string& c : spectrumKeyColumns()) v.push_back(csvColumn(c));
    return v;
  }();
  return spectrumKeyOf(f, at);
}

std::string spectrumKeyOfRow(const CsvRow& row) { return spectrumKeyOfCsvRow(splitCsvLine(formatCsvRow(row))); }

std::string spectrumKeyOfLine(const std::vector<std::string>& f) {
  static const std::vector<size_t> at = [] {
    std::vector<size_t> v(spectrumKeyColumns().size());
    for (size_t i = 0; i < v.size(); ++i) v[i] = i;
    return v;
  }();
  return spectrumKeyOf(f, at);
}

}  // namespace aliaslab
