#include "study/records/lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <ctime>

#include "core/error.h"
#include "core/files.h"

namespace aliaslab {

namespace {
std::string holderText(int fd) {
  std::string text;
  char buf[512];
  ssize_t n = 0;
  ::lseek(fd, 0, SEEK_SET);
  while ((n = ::read(fd, buf, sizeof buf)) > 0 && text.size() < 4096) text.append(buf, static_cast<size_t>(n));
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text.empty() ? "a run that has not yet written its name" : text;
}
}  // namespace

CsvLock::CsvLock(const std::string& csvPath, const std::string& command) : path_(lockPath(csvPath)) {
  // The lock file may be unlinked by its releasing holder between our open() and flock(): then we hold a lock on
  // a file nobody else sees, so check that the path still names our file, and try again when it does not.
  for (int attempt = 0; attempt < 100; ++attempt) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw FileError(path_, "cannot create the CSV's lock file: " + lastSystemError());
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const std::string holder = holderText(fd_);
      ::close(fd_), fd_ = -1;
      throw FileError(csvPath, "in use by another run (" + holder + ", lock " + path_ +
                                   "): one run writes a study CSV at a time; wait for it to finish, or give this "
                                   "run another {out} or {csv} (shards use {shard} i/N, each its own CSV)");
    }
    struct stat mine {}, named {};
    if (::fstat(fd_, &mine) == 0 && ::stat(path_.c_str(), &named) == 0 && mine.st_ino == named.st_ino &&
        mine.st_dev == named.st_dev)
      break;
    ::close(fd_), fd_ = -1;
  }
  if (fd_ < 0) throw FileError(path_, "cannot take the CSV's lock (the lock file keeps changing)");
  char host[256] = "?";
  ::gethostname(host, sizeof host - 1);
  char when[64] = "";
  const std::time_t now = std::time(nullptr);
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&now));
  const std::string text =
      command + " process " + std::to_string(::getpid()) + " on " + host + ", started " + when + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, text.data(), text.size(), 0) < 0) {
    // the lock holds without the holder's name; not worth failing the run for
  }
}

CsvLock::~CsvLock() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());  // while still holding it, so nobody takes a lock on a file about to vanish unseen
  ::close(fd_);
}

}  // namespace aliaslab
