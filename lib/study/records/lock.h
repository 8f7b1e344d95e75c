// One run per study CSV: a lock file beside the CSV.
//
// CsvLock takes an exclusive flock(2) on "<csv>.lock" and writes the holder
// into it (process id, host, start time, command). A second run on the same
// CSV fails at once with FileError naming the CSV and that holder. The
// kernel drops a flock when its process ends, however it ends (kill -9, a
// crash), so a lock file left behind by a dead run is stale by construction:
// the next run simply takes it. The lock file is removed on release.
//
// Shards write their own CSVs (study.shard-i-of-N.csv), so they take
// different locks and run side by side; the reference cache needs no lock
// (its files are written to temporaries and renamed, see reference.h).
#pragma once
#include <string>

namespace aliaslab {

class CsvLock {
 public:
  /// Takes the lock of `csvPath` for `command` (e.g. "sweep"). Throws FileError when another live run holds it.
  CsvLock(const std::string& csvPath, const std::string& command);
  ~CsvLock();
  CsvLock(const CsvLock&) = delete;
  CsvLock& operator=(const CsvLock&) = delete;

  /// The lock file's path ("<csv>.lock").
  static std::string lockPath(const std::string& csvPath) { return csvPath + ".lock"; }

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace aliaslab
