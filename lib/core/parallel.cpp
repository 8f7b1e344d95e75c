#include "core/parallel.h"

#include <time.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <numeric>
#include <random>
#include <thread>
#include <vector>

namespace aliaslab {

int resolveThreads(int requested) {
  if (requested > 0) return requested;
  return std::max(1u, std::thread::hardware_concurrency());
}

namespace {
std::atomic<uint64_t> shuffleSeed{0};
/// CPU seconds of the threads parallelFor started from this thread, added when joined.
thread_local double joinedCpuSeconds = 0;

double ownCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}
}  // namespace

double threadCpuSeconds() { return ownCpuSeconds() + joinedCpuSeconds; }

void setParallelShuffle(uint64_t seed) { shuffleSeed = seed; }

void parallelFor(int n, int threads, const std::function<void(int)>& userBody) {
  std::vector<int> order;
  if (const uint64_t seed = shuffleSeed.load(); seed != 0 && n > 1) {
    order.resize(n);
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937_64(seed ^ static_cast<uint64_t>(n)));
  }
  const std::function<void(int)> shuffled = [&](int i) { userBody(order[i]); };
  const std::function<void(int)>& body = order.empty() ? userBody : shuffled;
  threads = std::min(resolveThreads(threads), std::max(n, 1));
  if (threads <= 1) {
    for (int i = 0; i < n; ++i) body(i);
    return;
  }
  std::atomic<int> next{0};
  std::exception_ptr error;
  std::mutex errorMutex;
  auto worker = [&] {
    for (int i; (i = next.fetch_add(1)) < n;) {
      try {
        body(i);
      } catch (...) {
        std::lock_guard lock(errorMutex);
        if (!error) error = std::current_exception();
        next = n;  // stop handing out work
      }
    }
  };
  std::vector<std::thread> pool;
  std::vector<double> poolCpu(threads, 0.0);  // each started thread's CPU seconds, its own slot
  for (int t = 1; t < threads; ++t)
    pool.emplace_back([&, t] {
      worker();
      poolCpu[t] = threadCpuSeconds();
    });
  worker();
  for (auto& t : pool) t.join();
  for (double c : poolCpu) joinedCpuSeconds += c;
  if (error) std::rethrow_exception(error);
}

}  // namespace aliaslab
