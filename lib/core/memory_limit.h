// The memory this process may use, and the check that fails before a large
// allocation instead of std::bad_alloc after a long wait.
#pragma once
#include <string>

namespace aliaslab {

/// Fails before allocating: throws OptionError(key) when `bytes` (an estimate of what `what` needs) exceeds
/// the memory this process may use (memoryLimit), with both figures and the limit's source in the message
/// (instead of std::bad_alloc after a long wait).
void requireMemory(double bytes, const std::string& key, const std::string& what);

/// The memory this process may use: the least of physical memory, the address-space limit (RLIMIT_AS) and the
/// cgroup's limit (v2 memory.max, v1 memory.limit_in_bytes), in bytes, and which of them it is.
struct MemoryLimit {
  double bytes = 0;    ///< 0 when nothing is known
  std::string source;  ///< "physical memory", "the address-space limit (ulimit -v)", "the cgroup memory limit"
};
MemoryLimit memoryLimit();

}  // namespace aliaslab
