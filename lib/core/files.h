// Whole-file writes that never leave a half-written file: write a temporary
// beside the target, then rename it into place (atomic on one file system).
//
// Also runProgram(): a helper program (the Python charts) run with its
// arguments passed as they are, not through a shell.
#pragma once
#include <string>
#include <vector>

namespace aliaslab {

/// A temporary name beside `path`, unique to this process and call, ending in
/// path's extension (image writers choose the format by it):
/// "<path>.partial.<pid>.<n><ext>". Concurrent writers of one target (shards
/// sharing an output folder) never share a temporary.
std::string temporaryPathFor(const std::string& path);

/// Writes text to a file atomically (temporary + rename). Throws FileError.
void writeTextFile(const std::string& path, const std::string& text);

/// Runs argv[0] (found on PATH when it has no slash) with argv[1..] as its arguments, without a shell (so
/// paths need no quoting), waits, and returns its exit status (-1 when it could not start or was killed).
int runProgram(const std::vector<std::string>& argv);

}  // namespace aliaslab
