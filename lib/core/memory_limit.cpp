#include "core/memory_limit.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/error.h"

namespace aliaslab {

namespace {
// The first number in `file` (a cgroup limit), or 0 when it is missing, "max" or unreadable.
double limitInFile(const std::string& file) {
  std::ifstream in(file);
  std::string word;
  if (!(in >> word) || word.empty() || word.find_first_not_of("0123456789") != std::string::npos) return 0;
  try { return std::stod(word); } catch (const std::exception&) { return 0; }
}

// This process's cgroup memory limit (v2: memory.max of its group; v1: memory.limit_in_bytes), 0 when none.
double cgroupLimit() {
  std::ifstream in("/proc/self/cgroup");
  double least = 0;
  auto take = [&](double v) {
    if (v > 0 && v < 1e18 && (least == 0 || v < least)) least = v;
  };
  for (std::string line; std::getline(in, line);) {
    // "0::/path" (v2) or "N:memory:/path" (v1)
    const size_t a = line.find(':'), b = a == std::string::npos ? a : line.find(':', a + 1);
    if (b == std::string::npos) continue;
    const std::string controllers = line.substr(a + 1, b - a - 1), group = line.substr(b + 1);
    if (controllers.empty()) {
      // the group and its ancestors: the least limit applies
      for (std::filesystem::path g(group);; g = g.parent_path()) {
        take(limitInFile("/sys/fs/cgroup" + (g.string() == "/" ? std::string() : g.string()) + "/memory.max"));
        if (g == g.parent_path() || g.empty()) break;
      }
    } else if (("," + controllers + ",").find(",memory,") != std::string::npos) {
      take(limitInFile("/sys/fs/cgroup/memory" + group + "/memory.limit_in_bytes"));
      take(limitInFile("/sys/fs/cgroup/memory/memory.limit_in_bytes"));
    }
  }
  return least;
}
}  // namespace

MemoryLimit memoryLimit() {
  MemoryLimit m;
  auto take = [&](double v, const char* source) {
    if (v > 0 && (m.bytes == 0 || v < m.bytes)) m.bytes = v, m.source = source;
  };
  take(static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGESIZE)),
       "physical memory");
  struct rlimit r{};
  if (::getrlimit(RLIMIT_AS, &r) == 0 && r.rlim_cur != RLIM_INFINITY)
    take(static_cast<double>(r.rlim_cur), "the address-space limit (ulimit -v)");
  take(cgroupLimit(), "the cgroup (container) memory limit");
  return m;
}

void requireMemory(double bytes, const std::string& key, const std::string& what) {
  const MemoryLimit limit = memoryLimit();
  if (limit.bytes > 0 && bytes > limit.bytes) {
    char text[320];
    std::snprintf(text, sizeof text, "%s needs about %.2f GB of memory, more than this process may use (%.2f GB, %s)",
                  what.c_str(), bytes / 1e9, limit.bytes / 1e9, limit.source.c_str());
    throw OptionError(key, text);
  }
}

}  // namespace aliaslab
