// The sweep's memory: the documented bound on its in-flight task state, and the scheduler's count of it.
//
// Protocol: the sweep holds one group at a time; within it at most W = min(seeds, threads) sample sets are in
// flight, each with its Accumulator and the images of its rows, plus up to `threads` importance-traced buffers.
// InFlight counts those bytes as tasks add and remove them and keeps the peak; sweepMemoryBound is the bound
// that peak never exceeds (tests/programs/sweep_parallel_test.cpp), and validation checks it against the machine's memory
// before any work (study/validate.h validateStudy). This header depends on nothing of the sweep or its
// configuration, so both can use it.
#pragma once
#include <atomic>
#include <cstddef>

namespace aliaslab {

/// The documented bound on the sweep's in-flight task state (bytes) for one group: with
/// W = min(seeds, threads) sample sets in flight, W x (sample buffer + Accumulator + rowsPerGroup images)
/// plus up to `threads` importance-traced buffers. Sample buffer = width x height x spp x sizeof(FilmSample)
/// (24 B); Accumulator = width x height x (weightedRows + 1) x 4 doubles; image = width x height x 3 floats.
/// runSweep's summary.peakInFlightBytes never exceeds it (tests/programs/sweep_parallel_test.cpp).
size_t sweepMemoryBound(int threads, int width, int height, int spp, size_t rowsPerGroup, size_t weightedRows,
                        int seeds);

/// Bytes of one row image (3 floats per pixel).
inline size_t imageBytes(int width, int height) { return size_t(width) * height * 3 * sizeof(float); }

/// The scheduler's count of in-flight task state (sample sets, accumulators, images), and its peak. Thread-safe.
class InFlight {
 public:
  void add(size_t bytes) {
    const size_t now = bytes_.fetch_add(bytes) + bytes;
    size_t peak = peak_.load();
    while (now > peak && !peak_.compare_exchange_weak(peak, now)) {
    }
  }
  void remove(size_t bytes) { bytes_.fetch_sub(bytes); }
  size_t peak() const { return peak_.load(); }

 private:
  std::atomic<size_t> bytes_{0}, peak_{0};
};

}  // namespace aliaslab
