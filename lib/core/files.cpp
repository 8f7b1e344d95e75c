#include "core/files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <map>
#include <regex>

#include "core/error.h"
#include "core/process.h"

namespace aliaslab {

std::string temporaryPathFor(const std::string& path) {
  static std::atomic<unsigned long> counter{0};
  return path + ".partial." + std::to_string(::getpid()) + "." + std::to_string(counter++) +
         std::filesystem::path(path).extension().string();
}

std::string specialFileKind(const std::string& path) {
  struct stat st{};
  if (path.empty() || ::stat(path.c_str(), &st) != 0) return "";
  if (S_ISREG(st.st_mode)) return "";
  if (S_ISDIR(st.st_mode)) return "a folder";
  if (S_ISFIFO(st.st_mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(st.st_mode)) return "a socket";
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "a device";
  return "not a regular file";
}

void requireRegularFile(const std::string& path, const std::string& use) {
  const std::string kind = specialFileKind(path);
  if (!kind.empty()) throw FileError(path, "is " + kind + ", not a regular file: " + use);
}

std::string lastSystemError() { return std::strerror(errno); }

std::string writeFully(int fd, const std::string& text) {
  for (size_t done = 0; done < text.size();) {
    errno = 0;
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return lastSystemError();
    if (n == 0) return "the write made no progress (file system full?)";
    done += static_cast<size_t>(n);
  }
  return "";
}

OutputTarget outputTarget(const std::string& path) {
  namespace fs = std::filesystem;
  OutputTarget t{path, false};
  std::error_code ec;
  // A device, FIFO or socket (links followed by the kernel): written through under the name given, which also
  // works for /dev/stdout when it is a pipe (its link names "pipe:[...]", no path).
  struct stat info{};
  if (::stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode)) {
    t.special = true;
    return t;
  }
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

void refuseOutputsOverInputs(const std::vector<OutputFile>& outputs, const std::vector<std::string>& inputs) {
  namespace fs = std::filesystem;
  std::map<std::string, size_t> written;  // an output's file (links and dots resolved) -> its first index
  for (size_t k = 0; k < outputs.size(); ++k) {
    const OutputFile& o = outputs[k];
    if (o.path.empty()) continue;
    for (const std::string& in : inputs)
      if (!in.empty() && sameFile(o.path, in))
        throw OptionError(o.key, "'" + o.path + "' is also an input ('" + in +
                                     "'); writing it would destroy the input: give the output another name");
    std::error_code ec;
    fs::path file = fs::weakly_canonical(o.path, ec);
    if (ec) file = fs::absolute(o.path, ec).lexically_normal();
    const auto [it, fresh] = written.emplace(file.string(), k);
    if (!fresh)
      throw OptionError(o.key, "'" + o.path + "' is also written as " + outputs[it->second].key + " ('" +
                                   outputs[it->second].path + "'); one would replace the other: give each output "
                                   "its own name");
  }
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
    if (processRunning(pid)) continue;  // its writer still runs
    stale.push_back(it->path());
  }
  for (const fs::path& p : stale) removed += fs::remove(p, ec) ? 1 : 0;
  return removed;
}

void writeTextFile(const std::string& path, const std::string& text) {
  const OutputTarget target = outputTarget(path);
  std::string why;
  // Writes all of `text` to fd; false with `why` set on failure.
  auto writeAllTo = [&](int fd) {
    why = writeFully(fd, text);
    return why.empty();
  };
  if (target.special) {  // a device or FIFO: write through, no temporary
    // O_NONBLOCK: a FIFO nobody reads fails at once (ENXIO) instead of blocking; then writes block as usual.
    const int fd = ::open(target.path.c_str(), O_WRONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0 && errno == ENXIO) throw FileError(path, "cannot open for writing: no process reads this FIFO");
    if (fd < 0) throw FileError(path, "cannot open for writing: " + lastSystemError());
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    const bool ok = writeAllTo(fd);
    ::close(fd);
    if (!ok) throw FileError(path, "write failed: " + why);
    return;
  }
  const std::string tmp = temporaryPathFor(target.path);
  std::error_code ec;
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw FileError(path, "cannot open for writing: " + lastSystemError());
  bool ok = writeAllTo(fd);
  if (ok && ::fsync(fd) != 0) ok = false, why = lastSystemError();
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

}  // namespace aliaslab
