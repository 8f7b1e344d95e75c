// Joining the CSVs of a sharded study into one (the sweep's merge job).
//
// A study run as N shards writes study.shard-i-of-N.csv (i = 0..N-1), each
// with its spectra and images beside it. mergeStudy checks the set of shard
// files (checkShardSet: every i once, one N), holds the output CSV's lock,
// merges the rows in canonical order (study/csv.h mergeCsvFiles), the shards'
// spectra (study/spectrum_files.h mergeSpectrumFiles) and, when the shards
// wrote images beside the output, draws the study's contact sheets.
// Errors: OptionError keyed "merge" for the set of inputs, FileError and
// ParseError for the files themselves.
#pragma once
#include <string>
#include <vector>

namespace aliaslab {

/// Checks the inputs of a merge: among files named *shard-i-of-N.csv (the sweep's own names), every i in
/// 0..N-1 must be there once, all with the same N, so a merge cannot silently lack a shard's rows. Files named
/// otherwise (a chosen CSV path) are not checked. Throws OptionError("merge").
void checkShardSet(const std::vector<std::string>& inputs);

/// Merges the shard CSVs `inputs` into `out` (see the top of this file); `command` names the job in the lock
/// file (e.g. "sweep --merge", shown to a second run that finds the lock held).
void mergeStudy(const std::string& out, const std::vector<std::string>& inputs, const std::string& command);

}  // namespace aliaslab
