// The sweep's background writer: a finished group's CSV and spectrum lines are written on one background thread
// while the next group computes, in submission order.
//
// Protocol: at most one group is in the writer. submit() first waits for the previous job (and rethrows its
// error), so an interrupted run loses at most the group being written besides the one computing; both are
// recomputed on resume (a torn CSV tail is cut). A job touches only what its owner keeps alive until the writer
// is joined: declare the GroupWriter after what its jobs touch, so it is destroyed (joined) before them.
#pragma once
#include <functional>
#include <future>

#include "core/stopwatch.h"

namespace aliaslab {

class GroupWriter {
 public:
  GroupWriter() = default;
  GroupWriter(const GroupWriter&) = delete;
  GroupWriter& operator=(const GroupWriter&) = delete;
  ~GroupWriter() {
    if (job_.valid()) job_.wait();
  }
  /// Waits for the write in progress; returns the main thread's seconds spent waiting. Rethrows its error.
  double wait() {
    if (!job_.valid()) return 0;
    const Stopwatch waited;
    job_.get();
    return waited.seconds();
  }
  /// Waits for the previous job, then starts `job`; returns the seconds spent waiting.
  double submit(std::function<void()> job) {
    const double waited = wait();
    job_ = std::async(std::launch::async, [job = std::move(job), this] {
      const Stopwatch writing;
      job();
      seconds_ += writing.seconds();  // read only after wait()
    });
    return waited;
  }
  /// Seconds the writer spent writing (off the critical path); read after wait().
  double seconds() const { return seconds_; }

 private:
  std::future<void> job_;
  double seconds_ = 0;
};

}  // namespace aliaslab
