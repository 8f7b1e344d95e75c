// Whole-file writes that never leave a half-written file: write a temporary
// beside the target, then rename it into place (atomic on one file system).
#pragma once
#include <string>

namespace aliaslab {

/// A temporary name beside `path`, unique to this process and call, ending in
/// path's extension (image writers choose the format by it):
/// "<path>.partial.<pid>.<n><ext>". Concurrent writers of one target (shards
/// sharing an output folder) never share a temporary.
std::string temporaryPathFor(const std::string& path);

/// Writes text to a file atomically (temporary + rename). Throws FileError.
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace aliaslab
