// The spectrum key: what names a configuration's spectra in the study's spectrum files
// (study/records/spectrum_files.h). It is the values of the columns
//   scene,sampler,spp,filter,radius,reconstruction,prefilter
// joined by ',', exactly as the configuration's spectrum lines start; the same columns are columns of the study CSV
// (study/records/csv.h), so a study row finds its spectra by its key. spectrumKeyOf builds every key; the other
// functions only say where the values sit (a study CSV row's fields, a CsvRow, a spectrum line's fields).
// analysis/aliaslab_analysis/charts/spectra.py KEY spells the same columns for the Python readers.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace aliaslab {

struct CsvRow;  // study/records/csv.h

/// The key columns, in order: the first columns of a spectrum line.
const std::vector<std::string>& spectrumKeyColumns();
/// The key of the configuration whose values sit in `fields` at positions `at` (one per spectrumKeyColumns entry).
std::string spectrumKeyOf(const std::vector<std::string>& fields, const std::vector<size_t>& at);
/// The spectrum key of a configuration as its study CSV row (fields) gives it.
std::string spectrumKeyOfCsvRow(const std::vector<std::string>& csvFields);
/// The spectrum key of a configuration as its CsvRow gives it (the fields formatCsvRow writes).
std::string spectrumKeyOfRow(const CsvRow& row);
/// The spectrum key of a spectrum line (fields): its first fields.
std::string spectrumKeyOfLine(const std::vector<std::string>& lineFields);

}  // namespace aliaslab
