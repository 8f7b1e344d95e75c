// Whole-file writes that never leave a half-written file: write a temporary
// beside the target, then rename it into place (atomic on one file system);
// what a path is (a regular file, a folder, a FIFO, a device) before anything
// opens it; and the one rule that no output overwrites an input or another
// output. The memory a process may use is core/memory_limit.h, starting
// another program core/process.h.
#pragma once
#include <string>
#include <vector>

namespace aliaslab {

/// A temporary name beside `path`, unique to this process and call, ending in
/// path's extension (image writers choose the format by it):
/// "<path>.partial.<pid>.<n><ext>". Concurrent writers of one target (shards
/// sharing an output folder) never share a temporary.
std::string temporaryPathFor(const std::string& path);

/// Writes text to a file atomically (temporary + rename; see outputTarget for links and devices). Throws
/// FileError naming the file and the system's reason (e.g. "No space left on device").
void writeTextFile(const std::string& path, const std::string& text);

/// Where a write to `path` lands. Symbolic links are followed (the link stays a link and its final target is
/// replaced); `special` is true when that target exists and is not a regular file or folder (a device such as
/// /dev/stdout, a FIFO): text is then written straight through (no temporary, no rename), images are refused.
struct OutputTarget {
  std::string path;      ///< the final target (links resolved)
  bool special = false;  ///< an existing device, FIFO or socket
};
OutputTarget outputTarget(const std::string& path);

/// True when a and b name the same file (same inode when both exist, else the same normalised absolute path).
bool sameFile(const std::string& a, const std::string& b);

/// A file a program writes, with the key of the option that names it (the front end maps keys to flags).
struct OutputFile {
  std::string key;
  std::string path;
};

/// The one rule for outputs, in every program: called with every file the program will write (images, frame
/// names, CSVs, spectra, manifests, lock files) and every file it reads, before anything is written. Throws
/// OptionError(the output's key) when an output is an input (writing it would destroy the input: "'<path>' is
/// also an input ('<input>')") or is another output too (one would silently replace the other: "'<path>' is also
/// written as <other key>"). Empty paths are skipped.
void refuseOutputsOverInputs(const std::vector<OutputFile>& outputs, const std::vector<std::string>& inputs);

/// Removes the temporaries ("*.partial.<pid>.*", see temporaryPathFor) that a killed run left in `dir` and its
/// sub-folders: those whose process <pid> is no longer running. Returns how many were removed.
size_t removeStaleTemporaries(const std::string& dir);

/// What `path` is when it exists and is not a regular file: "a folder", "a FIFO", "a device", "a socket";
/// "" for a regular file (links followed) or a missing path. Never opens the file (a FIFO would block).
std::string specialFileKind(const std::string& path);

/// Throws FileError(path, "is a FIFO, not a regular file: <use>") when `path` exists and is not a regular file
/// (specialFileKind), before anything opens it. `use` says what the file was wanted for.
void requireRegularFile(const std::string& path, const std::string& use);

/// Writes all of `text` to `fd` (retrying short writes and EINTR); "" on success, else the system's reason
/// ("No space left on device"; never a stale errno: a write that makes no progress says so).
std::string writeFully(int fd, const std::string& text);

/// "<strerror(errno)>", e.g. "No space left on device", for messages after a failed system call.
std::string lastSystemError();

}  // namespace aliaslab
