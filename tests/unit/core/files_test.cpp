// Issue 31: core/files.h's checks of what a path is, whole writes with a true reason, text written through to a
// pipe (/dev/stdout when stdout is a pipe), and the memory limit that applies (core/memory_limit.h).
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/files.h"
#include "core/memory_limit.h"
#include "support/scratch_dir.h"

namespace fs = std::filesystem;
using namespace aliaslab;

namespace {
fs::path dir() {
  static const fs::path d = [] {
    const fs::path p = aliaslab::testing::scratchDir("aliaslab_files_test");
    fs::create_directories(p);
    return p;
  }();
  return d;
}
}  // namespace

TEST(Files, SpecialFileKindNamesWhatIsNotARegularFileWithoutOpeningIt) {
  const fs::path fifo = dir() / "fifo", file = dir() / "file", folder = dir() / "folder";
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  std::ofstream(file) << "x";
  fs::create_directories(folder);
  EXPECT_EQ(specialFileKind(file.string()), "");
  EXPECT_EQ(specialFileKind((dir() / "missing").string()), "");
  EXPECT_EQ(specialFileKind(folder.string()), "a folder");
  EXPECT_EQ(specialFileKind("/dev/null"), "a device");
  EXPECT_NE(specialFileKind(fifo.string()).find("FIFO"), std::string::npos);  // returns: nothing opened it
  try {
    requireRegularFile(fifo.string(), "a scene is read from a regular file");
    FAIL() << "a FIFO was accepted";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(fifo.string() + ": is a FIFO"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(requireRegularFile(file.string(), "x"));
}

TEST(Files, AFifoNobodyReadsIsRefusedAtOnceNotBlockedOn) {
  const fs::path fifo = dir() / "lonely";
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  try {
    writeTextFile(fifo.string(), "text\n");
    FAIL() << "written";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("no process reads this FIFO"), std::string::npos) << e.what();
  }
}

TEST(Files, TextGoesThroughDevStdoutWhenItIsAPipe) {
  int p[2];
  ASSERT_EQ(::pipe(p), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // stdout is the pipe: /dev/stdout -> /proc/self/fd/1 -> "pipe:[...]", which is no path
    ::dup2(p[1], 1);
    ::close(p[0]);
    try {
      writeTextFile("/dev/stdout", "through the pipe\n");
    } catch (...) {
      ::_exit(3);
    }
    ::_exit(0);
  }
  ::close(p[1]);
  std::string got;
  char buf[256];
  for (ssize_t n; (n = ::read(p[0], buf, sizeof buf)) > 0;) got.append(buf, size_t(n));
  ::close(p[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "writeTextFile threw";
  EXPECT_EQ(got, "through the pipe\n");
}

TEST(Files, WriteFullyGivesTheSystemsReasonNeverAStaleOne) {
  const int fd = ::open("/dev/full", O_WRONLY | O_CLOEXEC);
  if (fd < 0) GTEST_SKIP() << "no /dev/full";
  errno = 0;
  EXPECT_EQ(writeFully(fd, "abc"), "No space left on device");
  ::close(fd);
  const fs::path f = dir() / "whole";
  const int g = ::open(f.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  EXPECT_EQ(writeFully(g, std::string(1 << 20, 'y')), "");
  ::close(g);
  EXPECT_EQ(fs::file_size(f), size_t(1) << 20);
}

TEST(Files, TheMemoryLimitIsTheAddressSpaceLimitWhenThatIsLower) {
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer reserves terabytes of shadow address space at start-up, so no program starts under an
  // address-space limit (ulimit -v) in the sanitizer build; the release suite runs this test.
  GTEST_SKIP() << "an address-space limit cannot be set under AddressSanitizer";
#endif
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // in a child: the limit stays there
    struct rlimit r{};
    r.rlim_cur = r.rlim_max = rlim_t(3) << 30;  // 3 GiB
    if (::setrlimit(RLIMIT_AS, &r) != 0) ::_exit(4);
    const MemoryLimit m = memoryLimit();
    if (m.bytes > double(rlim_t(3) << 30)) ::_exit(1);
    if (m.bytes == double(rlim_t(3) << 30) && m.source.find("ulimit -v") == std::string::npos) ::_exit(2);
    try {
      requireMemory(4e9, "size", "a 1 x 1 image");
      ::_exit(3);
    } catch (const OptionError& e) {
      ::_exit(std::string(e.what()).find("more than this process may use") == std::string::npos ? 5 : 0);
    }
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: limit above RLIMIT_AS, 2: source not named, 3: not refused, 5: message";
  const MemoryLimit here = memoryLimit();
  EXPECT_GT(here.bytes, 0);
  EXPECT_FALSE(here.source.empty());
}
