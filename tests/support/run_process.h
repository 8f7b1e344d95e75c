// Child processes for the program tests: start a program with posix_spawn in
// a given working folder, stdout and stderr sent to files, and wait for it,
// telling a normal exit from a signal; or run a shell command line the same way.
#pragma once
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace aliaslab::testing {

/// Starts argv[0] (a path) with arguments argv[1..] in folder `cwd`;
/// stdout and stderr go to the files `out` and `err` (truncated).
inline pid_t spawnProcess(const std::vector<std::string>& argv, const std::string& cwd, const std::string& out,
                          const std::string& err) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("posix_spawn " + argv[0] + " failed: " + std::to_string(rc));
  return pid;
}

struct ProcessResult {
  bool signaled = false;  ///< ended by a signal (a crash, or our SIGKILL)
  int signal = 0;         ///< that signal
  int exitCode = -1;      ///< the exit code of a normal exit
  std::string out, err;   ///< what it printed
};

inline std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Waits for `pid`, then reads the files its output went to.
inline ProcessResult waitProcess(pid_t pid, const std::string& out, const std::string& err) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
  }
  ProcessResult r;
  r.signaled = WIFSIGNALED(status);
  r.signal = r.signaled ? WTERMSIG(status) : 0;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readText(out);
  r.err = readText(err);
  return r;
}

/// Runs a program to its end; its output goes through files in `logDir`.
inline ProcessResult runProcess(const std::vector<std::string>& argv, const std::string& cwd,
                                const std::string& logDir) {
  const std::string out = logDir + "/stdout.txt", err = logDir + "/stderr.txt";
  return waitProcess(spawnProcess(argv, cwd, out, err), out, err);
}

/// Runs the shell command line `command` (std::system) with stdout sent to the file `out` and stderr to `err`
/// (to `out` as well when `err` is empty), then reads them; exitCode is -1 unless it exited normally.
inline ProcessResult runShell(const std::string& command, const std::string& out, const std::string& err = "") {
  const int status = std::system((command + " > " + out + (err.empty() ? " 2>&1" : " 2> " + err)).c_str());
  ProcessResult r;
  r.signaled = WIFSIGNALED(status);
  r.signal = r.signaled ? WTERMSIG(status) : 0;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readText(out);
  r.err = err.empty() ? "" : readText(err);
  return r;
}

}  // namespace aliaslab::testing
