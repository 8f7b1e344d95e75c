// core/process.h: a program started without a shell gets its arguments as they are and reports its exit status;
// a process that has ended is seen as ended (removeStaleTemporaries relies on it).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/process.h"

using namespace aliaslab;

TEST(Process, RunProgramReturnsTheExitStatus) {
  EXPECT_EQ(runProgram({"sh", "-c", "exit 3"}), 3);
  EXPECT_EQ(runProgram({"true"}), 0);
}

TEST(Process, RunProgramPassesArgumentsAsTheyAreWithoutAShell) {
  // Through a shell, "a b" would be two words and test(1) would see a malformed expression.
  EXPECT_EQ(runProgram({"test", "a b", "=", "a b"}), 0);
  EXPECT_EQ(runProgram({"test", "a b", "=", "a  b"}), 1);
}

TEST(Process, RunProgramGivesMinusOneWhenItCannotStartOrIsKilled) {
  EXPECT_EQ(runProgram({}), -1);
  EXPECT_EQ(runProgram({"/nonexistent/aliaslab-no-such-program"}), -1);
  EXPECT_EQ(runProgram({"sh", "-c", "kill -9 $$"}), -1);
}

TEST(Process, ProcessRunningSeesThisProcessAndNotAnEndedChild) {
  EXPECT_TRUE(processRunning(::getpid()));
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) ::_exit(0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_FALSE(processRunning(child));
}
