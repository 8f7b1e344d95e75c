// LDR-FLIP as defined (docs/flip.md), one pixel at a time with libm's cube root, hypotenuse and powers in double
// precision: the reference implementation that the fast one (flip.h) is tested against. It is the code the
// sweep used up to a22d95c, bit for bit. Not used by the programs; tests and benchmarks call it.
#pragma once
#include <vector>

#include "core/image.h"
#include "measure/flip/flip.h"

namespace aliaslab {

/// The definition's per-pixel map (same protocol as flipMap).
std::vector<float> flipMapDefinition(const Image& test, const Image& reference,
                                     double pixelsPerDegree = kFlipDefaultPixelsPerDegree);
/// Its mean over the pixels (a double sum of the float map, as meanFlip).
double meanFlipDefinition(const Image& test, const Image& reference,
                          double pixelsPerDegree = kFlipDefaultPixelsPerDegree);

}  // namespace aliaslab
