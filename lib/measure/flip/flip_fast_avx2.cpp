// The fast FLIP stages on four pixels per AVX instruction (flip_fast_kernels.h). This file alone is built with
// -mavx2 (CMakeLists.txt); flip_fast.cpp calls it only where the CPU has AVX2. It includes nothing that the
// other translation units share code with (raw pointers in, unnamed-namespace templates), so no AVX2 code can
// stand in for theirs at link time.
#include "measure/flip/flip_fast_kernels.h"

namespace aliaslab::flipkernels {

void planesAvx2(const LinearIn& in, const Planes& out, size_t n) { planesRange<4>(in, out, n); }

void combineAvx2(const PlanesIn& t, const PlanesIn& r, float* out, size_t n, double cmax) {
  combineRange<8>(t, r, out, n, cmax);
}

}  // namespace aliaslab::flipkernels
