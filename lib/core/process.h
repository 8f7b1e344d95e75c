// Other processes: starting a program without a shell and waiting for it,
// and asking whether a process still runs (a killed writer's temporaries).
#pragma once
#include <string>
#include <vector>

namespace aliaslab {

/// Runs argv[0] (found on PATH when it has no slash) with argv[1..] as its arguments, without a shell (so
/// paths need no quoting), waits, and returns its exit status (-1 when it could not start or was killed).
int runProgram(const std::vector<std::string>& argv);

/// True while process `pid` runs (or exists but belongs to another user); false once it has ended.
bool processRunning(long pid);

}  // namespace aliaslab
