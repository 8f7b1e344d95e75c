// What the CPU offers the vector paths: the one place the library asks the processor for its features.
//
// Every fast path that has an AVX2 (or AVX2 + FMA) twin asks cpuFeatures() which one to run: the BVH's 8-wide
// nodes (accel/bvh_trace.cpp), FilterBatch's 8 lanes (filter/filter_simd.h), the splat's 8-sample set-up and its
// AVX2 + FMA accumulation (film/splat_pass.cpp, film/splat_kernels.cpp) and FLIP's 4-lane convolution and
// colour stages (measure/flip/flip_convolve.cpp, measure/flip/flip_fast.cpp). Each twin computes the same bits as its
// SSE path, so the answer changes the speed, never a result.
//
// The processor is asked once. A test compares the paths by running the same work under a ScopedCpuFeatures,
// which makes cpuFeatures() report at most the features it names (on every thread) until it is destroyed: the
// code then runs as on a CPU without the others. Overrides nest; one alive at a time per test is the intended
// use (they are not meant to be made concurrently from several threads).
#pragma once

namespace aliaslab {

struct CpuFeatures {
  bool avx2 = false;
  bool fma = false;
};

/// The features the code may use: the processor's, less any that a ScopedCpuFeatures has withheld.
CpuFeatures cpuFeatures();

/// While alive, cpuFeatures() reports only features both the processor and `allowed` have (e.g. CpuFeatures{}:
/// the SSE paths everywhere); the previous setting comes back when it is destroyed.
class ScopedCpuFeatures {
 public:
  explicit ScopedCpuFeatures(CpuFeatures allowed);
  ~ScopedCpuFeatures();
  ScopedCpuFeatures(const ScopedCpuFeatures&) = delete;
  ScopedCpuFeatures& operator=(const ScopedCpuFeatures&) = delete;

 private:
  unsigned previous_;
};

}  // namespace aliaslab
