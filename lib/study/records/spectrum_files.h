// The study's spectrum files: each scene's radial error and noise spectra
// (measure/spectrum.h, docs/spectrum.md) as a long-format CSV beside the
// study CSV, one line per (configuration, kind, bin).
//
// Protocol: the sweep appends each group's configurations with
// appendSpectrumCsv (one write per call; a torn last line from a killed run
// is cut first), and canonicaliseSpectrumCsv puts a finished file in
// canonical order (sorted by key, the last copy of a re-measured
// configuration kept), so a resumed or sharded study ends with the same
// file as one uninterrupted run. The files live at spectrumCsvPath; merging
// shards joins them per scene (mergeSpectrumFiles). Errors are FileError.
#pragma once
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "measure/spectrum.h"

namespace aliaslab {

/// Appends the spectra of one configuration to a long-format CSV with the header
///   scene,sampler,spp,filter,radius,reconstruction,prefilter,kind,bin,frequency,power,energy
/// (kind = error or noise; one line per bin), creating it with the header when missing. One write per
/// call; a torn last line from a killed run is cut first. Throws FileError.
void appendSpectrumCsv(const std::string& path, const std::string& keyFields, const SpectrumMetrics& m);
/// The same for several configurations (key fields, spectra) in one write (the sweep: one per group).
void appendSpectrumCsv(const std::string& path,
                       const std::vector<std::pair<std::string, const SpectrumMetrics*>>& configurations);
/// Rewrites a spectrum CSV sorted by its key columns, keeping the last copy of a repeated
/// (configuration, kind, bin) line (a configuration re-measured after an interruption).
void canonicaliseSpectrumCsv(const std::string& path);
/// The header of the spectrum CSV (no newline).
const std::string& spectrumCsvHeader();
/// Where the sweep writes a scene's spectra for the study CSV `studyCsv`: <its folder>/spectra/<scene>.csv,
/// or <scene>.<CSV stem>.csv when the CSV is not called study.csv (shards, --csv), so shards never share one
/// (a trailing .gz is not part of the name: study.csv.gz's are study.csv's).
std::string spectrumCsvPath(const std::string& studyCsv, const std::string& scene);
/// The spectra of the shard CSVs `inputs` (each shard's spectrumCsvPath files) joined per scene into
/// spectrumCsvPath(out, scene), in canonical order (study/records/merge.h). Each shard's spectra must be complete for
/// the configurations of its CSV (checkSpectrumFile), or FileError naming the file and what is wrong, before
/// anything is written. Returns the files written.
std::vector<std::string> mergeSpectrumFiles(const std::string& out, const std::vector<std::string>& inputs);

/// Checks the spectra of every shard CSV of `inputs` (checkSpectrumFile for each scene of its rows). FileError.
void checkShardSpectra(const std::vector<std::string>& inputs);


/// Checks that the spectrum CSV `path` is whole and holds every configuration of `configurations` (spectrum key
/// fields, spectrumKeyOfCsvRow): present, a regular file, not empty, the spectrum header, no cut last line,
/// 12 fields a line, kind error or noise, and for every configuration both kinds over the same bins as every
/// other configuration of the file. Throws FileError (with the line where one applies) otherwise.
void checkSpectrumFile(const std::string& path, const std::vector<std::string>& configurations);

/// The configurations (key fields) whose spectra the spectrum CSV `path` holds whole: both kinds over the bins most
/// of its configurations have (a torn last line ignored; none when the file is missing); `present`, when given,
/// receives every configuration with at least one line. The sweep measures the present but not whole ones again on
/// resume, so a kill or a full disk during a spectra write costs nothing.
std::set<std::string> completeSpectra(const std::string& path, std::set<std::string>* present = nullptr);

}  // namespace aliaslab
