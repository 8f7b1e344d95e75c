#include "core/files.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>

#include "core/error.h"

namespace aliaslab {

std::string temporaryPathFor(const std::string& path) {
  static std::atomic<unsigned long> counter{0};
  return path + ".partial." + std::to_string(::getpid()) + "." + std::to_string(counter++) +
         std::filesystem::path(path).extension().string();
}

void requireMemory(double bytes, const std::string& key, const std::string& what) {
  const double physical = static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGESIZE));
  if (physical > 0 && bytes > physical) {
    char text[160];
    std::snprintf(text, sizeof text, "%s needs about %.1f GB of memory, more than this machine has (%.1f GB)",
                  what.c_str(), bytes / 1e9, physical / 1e9);
    throw OptionError(key, text);
  }
}

std::string lastSystemError() { return std::strerror(errno); }

OutputTarget outputTarget(const std::string& path) {
  namespace fs = std::filesystem;
  OutputTarget t{path, false};
  std::error_code ec;
  // Follow a chain of links (a bounded number, as the kernel does) to the file a write would reach.
  fs::path p(path);
  for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(p, ec)); ++hops) {
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) break;
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  t.path = p.string();
  const fs::file_status st = fs::status(p, ec);
  t.special = !ec && fs::exists(st) && !fs::is_regular_file(st) && !fs::is_directory(st);
  return t;
}

bool sameFile(const std::string& a, const std::string& b) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) {
    const bool eq = fs::equivalent(a, b, ec);
    if (!ec) return eq;
  }
  std::error_code ea, eb;
  const fs::path ca = fs::weakly_canonical(a, ea), cb = fs::weakly_canonical(b, eb);
  if (!ea && !eb) return ca == cb;
  return fs::absolute(a, ea).lexically_normal() == fs::absolute(b, eb).lexically_normal();
}

void refuseOutputOverInput(const std::string& key, const std::string& output,
                           const std::vector<std::string>& inputs) {
  for (const std::string& in : inputs)
    if (!in.empty() && sameFile(output, in))
      throw OptionError(key, "'" + output + "' is also an input ('" + in +
                                    "'); writing it would destroy the input: give the output another name");
}

size_t removeStaleTemporaries(const std::string& dir) {
  namespace fs = std::filesystem;
  static const std::regex name(R"(\.partial\.(\d+)\.\d+)");
  size_t removed = 0;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return 0;
  std::vector<fs::path> stale;
  for (auto it = fs::recursive_directory_iterator(dir, fs::directory_options::skip_permission_denied, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    std::smatch m;
    const std::string file = it->path().filename().string();
    if (!std::regex_search(file, m, name)) continue;
    long pid = 0;
    try { pid = std::stol(m[1].str()); } catch (const std::exception&) { continue; }
    if (pid <= 0 || pid == ::getpid()) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // its writer still runs
    stale.push_back(it->path());
  }
  for (const fs::path& p : stale) removed += fs::remove(p, ec) ? 1 : 0;
  return removed;
}

void writeTextFile(const std::string& path, const std::string& text) {
  const OutputTarget target = outputTarget(path);
  // Writes all of `text` to fd; false with errno set on failure.
  auto writeAllTo = [&](int fd) {
    for (size_t done = 0; done < text.size();) {
      const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;
      done += static_cast<size_t>(n);
    }
    return true;
  };
  if (target.special) {  // a device or FIFO: write through, no temporary
    const int fd = ::open(target.path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) throw FileError(path, "cannot open for writing: " + lastSystemError());
    const bool ok = writeAllTo(fd);
    const std::string why = lastSystemError();
    ::close(fd);
    if (!ok) throw FileError(path, "write failed: " + why);
    return;
  }
  const std::string tmp = temporaryPathFor(target.path);
  std::error_code ec;
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw FileError(path, "cannot open for writing: " + lastSystemError());
  bool ok = writeAllTo(fd) && ::fsync(fd) == 0;
  std::string why = ok ? "" : lastSystemError();
  if (::close(fd) != 0 && ok) ok = false, why = lastSystemError();
  if (!ok) {
    std::filesystem::remove(tmp, ec);
    throw FileError(path, "write failed: " + why);
  }
  std::filesystem::rename(tmp, target.path, ec);
  if (ec) {
    why = ec.message();  // (before remove() reuses ec)
    std::filesystem::remove(tmp, ec);
    throw FileError(path, "cannot move the finished file into place: " + why);
  }
}

int runProgram(const std::vector<std::string>& argv) {
  if (argv.empty()) return -1;
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  if (::posix_spawnp(&pid, args[0], nullptr, nullptr, args.data(), environ) != 0) return -1;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace aliaslab
