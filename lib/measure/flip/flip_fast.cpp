// Stages 2 and 3 of LDR-FLIP, fast (flip_planes.h): the definition's formulas with flip_fastmath.h's cube
// root, logarithm and power, on two pixels per SSE2 instruction, or four per AVX one where the CPU has AVX2
// (flip_fast_kernels.h; the same bits either way).

#include "core/cpu.h"
#include "measure/flip/flip.h"
#include "measure/flip/flip_fast_kernels.h"
#include "measure/flip/flip_planes.h"

namespace aliaslab {
namespace {

using namespace flipkernels;

bool useAvx2() { return cpuFeatures().avx2; }
PlanesIn view(const FlipPlanes& p) { return {p.L.data(), p.a.data(), p.b.data(), p.edge.data(), p.point.data()}; }

}  // namespace

FlipPlanes flipPlanesFast(const FlipLinear& in) {
  FlipPlanes p;
  p.width = in.width, p.height = in.height;
  const size_t n = in.gx.size();
  p.L.resize(n), p.a.resize(n), p.b.resize(n), p.edge.resize(n), p.point.resize(n);
  const LinearIn lin{in.rgb[0].data(), in.rgb[1].data(), in.rgb[2].data(), in.gx.data(),
                     in.gy.data(),     in.px.data(),     in.py.data()};
  const Planes out{p.L.data(), p.a.data(), p.b.data(), p.edge.data(), p.point.data()};
  if (useAvx2()) planesAvx2(lin, out, n);
  else planesRange<2>(lin, out, n);
  return p;
}

void flipCombineFast(const FlipPlanes& t, const FlipPlanes& r, float* out) {
  const double cmax = flipColourMax();
  if (useAvx2()) combineAvx2(view(t), view(r), out, t.L.size(), cmax);
  else combineRange<4>(view(t), view(r), out, t.L.size(), cmax);
}

}  // namespace aliaslab
