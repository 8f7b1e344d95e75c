// The processor's features, asked once, and the tests' override (core/cpu.h).
#include "core/cpu.h"

#include <atomic>

namespace aliaslab {
namespace {

constexpr unsigned kAvx2 = 1, kFma = 2;

unsigned bits(CpuFeatures f) { return (f.avx2 ? kAvx2 : 0) | (f.fma ? kFma : 0); }

unsigned detected() {
  static const unsigned found =
      bits({__builtin_cpu_supports("avx2") != 0, __builtin_cpu_supports("fma") != 0});
  return found;
}

/// The features a ScopedCpuFeatures allows (all when none is alive).
std::atomic<unsigned>& allowedBits() {
  static std::atomic<unsigned> allowed{~0u};
  return allowed;
}

}  // namespace

CpuFeatures cpuFeatures() {
  const unsigned on = detected() & allowedBits().load(std::memory_order_relaxed);
  return {(on & kAvx2) != 0, (on & kFma) != 0};
}

ScopedCpuFeatures::ScopedCpuFeatures(CpuFeatures allowed)
    : previous_(allowedBits().exchange(bits(allowed) & allowedBits().load())) {}

ScopedCpuFeatures::~ScopedCpuFeatures() { allowedBits().store(previous_); }

}  // namespace aliaslab
