// Deterministic parallel loops. Work items are independent and each writes
// only its own outputs, so the result never depends on the thread count.
#pragma once
#include <functional>

namespace aliaslab {

/// Number of threads to use when the user asked for `requested` (0 = all cores).
int resolveThreads(int requested);

/// Calls body(i) for i in [0, n) on `threads` threads (0 = all cores),
/// handing out items dynamically. Rethrows the first exception thrown by a body.
void parallelFor(int n, int threads, const std::function<void(int)>& body);

}  // namespace aliaslab
