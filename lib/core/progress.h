// ProgressBar of long work on stderr: a bar with percentage and ETA redrawn in
// place when stderr is a terminal, otherwise one plain line every `step`
// percent (logs stay readable). Thread-safe; quiet when disabled.
#pragma once
#include <chrono>
#include <mutex>
#include <string>

namespace aliaslab {

class ProgressBar {
 public:
  /// `total` work units (any positive weight), `label` shown before the bar,
  /// `step` the percentage between lines when stderr is not a terminal.
  ProgressBar(double total, std::string label, bool enabled = true, int step = 5);
  ~ProgressBar();

  /// Adds `units` of finished work and redraws when due.
  void advance(double units = 1);
  /// Prints the final state (100% and the elapsed time) once.
  void finish();

  /// "1h02m", "3m05s", "12s".
  static std::string formatDuration(double seconds);

 private:
  void draw(bool force);

  double total_, done_ = 0;
  std::string label_;
  bool enabled_, tty_, finished_ = false;
  int step_, lastStep_ = -1;
  std::chrono::steady_clock::time_point start_, lastDraw_;
  std::mutex mutex_;
};

}  // namespace aliaslab
