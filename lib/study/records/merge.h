// Joining the CSVs of a sharded study into one (the sweep's merge job).
//
// A study run as N shards writes study.shard-i-of-N.csv (i = 0..N-1), each
// with its spectra and images beside it. mergeStudy checks the set of shard
// files (checkShardSet: every i once, one N), holds the output CSV's lock,
// merges the rows in canonical order (mergeCsvFiles), the shards'
// spectra (study/records/spectrum_files.h mergeSpectrumFiles) and, when the shards
// wrote images beside the output, draws the study's contact sheets. The
// shards must hold one study: the values all its rows share (seeds, reference
// spp, frames and motion, alignment offsets, targets, each scene's size;
// study/records/study_identity.h) are the same in every shard, as a resume demands.
// An output that is a device or FIFO (/dev/stdout) receives the CSV only.
// Errors: OptionError keyed "merge" for the set of inputs, FileError and
// ParseError for the files themselves.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace aliaslab {

/// Checks the inputs of a merge: among files named *shard-i-of-N.csv (the sweep's own names), every i in
/// 0..N-1 must be there once, all with the same N, so a merge cannot silently lack a shard's rows. Files named
/// otherwise (a chosen CSV path) are not checked. Throws OptionError("merge").
void checkShardSet(const std::vector<std::string>& inputs);

/// Reads a shard for merging, strictly: a folder, an empty file, a header-only file (unless allowNoRows), a cut
/// last line or a row with the wrong number of fields is an error naming the file (and line). Throws FileError /
/// ParseError. `motion` (if given): whether the shard is of a study with frames (study/records/csv.h).
std::vector<std::string> readShardCsv(const std::string& path, bool allowNoRows = false, bool* motion = nullptr);

/// Merges shard CSVs into `out` in canonical order (rows with the same key and the same results are kept
/// once). Every input is read with readShardCsv; two rows with the same key but different results (timing and
/// threads aside) are an error naming both files and lines, and so are shards of different studies
/// (OptionError "merge" naming both files and the value that differs); `out` equal to an input is refused. A header-only
/// shard (study.shard-i-of-N.csv) is accepted only when the study has fewer groups than shards (every shard
/// with rows holds one group and no higher-numbered shard has rows).
/// `beforeWrite`, when given, runs after every input is checked and before `out` is written (mergeStudy checks
/// the shards' spectra there, so a damaged shard leaves nothing written).
void mergeCsvFiles(const std::string& out, const std::vector<std::string>& inputs,
                   const std::function<void()>& beforeWrite = {});

/// Merges the shard CSVs `inputs` into `out` (see the top of this file); `command` names the job in the lock
/// file (e.g. "sweep --merge", shown to a second run that finds the lock held).
void mergeStudy(const std::string& out, const std::vector<std::string>& inputs, const std::string& command);

}  // namespace aliaslab
