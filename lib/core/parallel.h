// Deterministic parallel loops. Work items are independent and each writes
// only its own outputs, so the result never depends on the thread count.
//
// Protocol for callers that combine results (the sweep, the references):
// each item writes into its own slot (indexed by i), and the caller folds the
// slots in index order after the loop returns. The order in which items run
// or finish is then irrelevant; setParallelShuffle() lets tests prove it by
// handing items out in a shuffled order.
//
// CPU time: threadCpuSeconds() is the calling thread's CPU time plus that of
// every thread parallelFor started from it (and, recursively, from those),
// each added when parallelFor joins it. So the difference of two readings
// around a piece of work on one thread is the CPU time of that work including
// its inner parallel loops (core/stopwatch.h CpuStopwatch), unaffected by
// other processes competing for the cores.
#pragma once
#include <cstdint>
#include <functional>

namespace aliaslab {

/// Number of threads to use when the user asked for `requested` (0 = all cores).
int resolveThreads(int requested);

/// Calls body(i) for i in [0, n) on `threads` threads (0 = all cores),
/// handing out items dynamically. Rethrows the first exception thrown by a body.
void parallelFor(int n, int threads, const std::function<void(int)>& body);

/// CPU seconds of the calling thread and of the threads parallelFor started from it, joined (see above).
double threadCpuSeconds();

/// Test hook: with seed != 0, every later parallelFor hands its items out in a
/// pseudo-random permutation drawn from the seed and n (also with one thread),
/// so results that depend on completion order change. 0 (the default) = in order.
void setParallelShuffle(uint64_t seed);

}  // namespace aliaslab
