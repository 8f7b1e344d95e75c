#include "core/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace aliaslab {

ProgressBar::ProgressBar(double total, std::string label, bool enabled, int step)
    : total_(std::max(total, 1e-9)), label_(std::move(label)), enabled_(enabled),
      tty_(::isatty(STDERR_FILENO) == 1), step_(std::max(step, 1)),
      start_(std::chrono::steady_clock::now()), lastDraw_(start_) {}

ProgressBar::~ProgressBar() {
  if (!finished_ && enabled_ && tty_) std::fputc('\n', stderr);
}

std::string ProgressBar::formatDuration(double s) {
  char buf[32];
  const long t = static_cast<long>(s + 0.5);
  if (t >= 3600) std::snprintf(buf, sizeof buf, "%ldh%02ldm", t / 3600, (t / 60) % 60);
  else if (t >= 60) std::snprintf(buf, sizeof buf, "%ldm%02lds", t / 60, t % 60);
  else std::snprintf(buf, sizeof buf, "%lds", t);
  return buf;
}

void ProgressBar::advance(double units) {
  std::lock_guard lock(mutex_);
  done_ = std::min(total_, done_ + units);
  draw(false);
}

void ProgressBar::finish() {
  std::lock_guard lock(mutex_);
  if (finished_) return;
  done_ = total_;
  draw(true);
  if (enabled_ && tty_) std::fputc('\n', stderr);
  finished_ = true;
}

void ProgressBar::draw(bool force) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double frac = done_ / total_;
  const int percent = static_cast<int>(frac * 100);
  const std::string eta = frac > 0 ? formatDuration(elapsed * (1 - frac) / frac) : "?";

  if (tty_) {
    // Redraw at most ten times a second.
    if (!force && now - lastDraw_ < std::chrono::milliseconds(100)) return;
    lastDraw_ = now;
    const int width = 30, filled = static_cast<int>(frac * width);
    std::string bar(filled, '#');
    bar.resize(width, '-');
    std::fprintf(stderr, "\r%s [%s] %3d%% elapsed %s ETA %s   ", label_.c_str(), bar.c_str(), percent,
                 formatDuration(elapsed).c_str(), eta.c_str());
  } else {
    const int stepNow = percent / step_;
    if (!force && stepNow == lastStep_) return;
    lastStep_ = stepNow;
    std::fprintf(stderr, "%s: %3d%% elapsed %s ETA %s\n", label_.c_str(), percent,
                 formatDuration(elapsed).c_str(), eta.c_str());
  }
  std::fflush(stderr);
}

}  // namespace aliaslab
