// The sweep program tests' common ground: the sweep binary, the zone-plate scene, the tiny study they all
// run (1 scene x 2 samplers x 2 spp = 4 groups, 3 filter/radius pairs each, one target, references cached
// in <work>/cache), a run of the program with its output in <work>/last_run.log, and a file's bytes.
#pragma once
#include "aliaslab_paths.h"

#include <filesystem>
#include <string>

#include "support/run_process.h"

namespace aliaslab::testing {

inline const std::string kSweepBin = std::string(ALIASLAB_BIN_DIR) + "/sweep";
inline const std::string kZonePlate = std::string(ALIASLAB_SOURCE_DIR) + "/scenes/zoneplate.txt";

/// The tiny study's arguments on `threads` threads (one thread: shards and whole runs print the same threads).
inline std::string tinySweepArgs(const std::filesystem::path& work, int threads) {
  return "--scenes " + kZonePlate + " --size 24 24 --samplers uniform,jittered --spp 4,16 --filters box,tent " +
         "--radii 1 --seeds 4 --ref-spp 256 --target area --threads " + std::to_string(threads) +
         " --quiet --no-images --cache " + (work / "cache").string();
}

/// Runs `sweep <args>` to its end, stdout and stderr logged in `work`.
inline ProcessResult runSweep(const std::string& args, const std::filesystem::path& work) {
  return runShell(kSweepBin + " " + args, (work / "last_run.log").string());
}

/// A file's bytes ("" when it cannot be read).
inline std::string fileBytes(const std::filesystem::path& p) { return readText(p.string()); }

}  // namespace aliaslab::testing
