// LDR-FLIP (flip.h, docs/flip.md), fast: stage 1 exact (flip_linear.cpp), stages 2 and 3 vectorised
// (flip_fast.cpp); the scalar definition they are tested against is flip_definition.cpp.
#include "measure/flip/flip.h"

#include <stdexcept>

namespace aliaslab {

FlipReference::FlipReference(const Image& reference, double ppd)
    : ppd_(ppd), planes_(flipPlanesFast(flipLinear(reference, ppd))) {}

FlipPlanes FlipReference::prepare(const Image& test) const {
  if (test.width() != planes_.width || test.height() != planes_.height)
    throw std::invalid_argument("flipMap: images of different sizes");
  return flipPlanesFast(flipLinear(test, ppd_));
}

namespace {
double meanOf(const std::vector<float>& m) {
  double s = 0;
  for (float v : m) s += v;
  return m.empty() ? 0.0 : s / m.size();
}
}  // namespace

std::vector<float> FlipReference::map(const Image& test) const {
  const FlipPlanes t = prepare(test);
  std::vector<float> out(t.L.size());
  flipCombineFast(t, planes_, out.data());
  return out;
}

double FlipReference::mean(const Image& test) const { return meanOf(map(test)); }

std::vector<double> meanFlips(const Image& test, const std::vector<const FlipReference*>& targets) {
  std::vector<double> means;
  if (targets.empty()) return means;
  const FlipPlanes t = targets.front()->prepare(test);
  std::vector<float> map(t.L.size());
  for (const FlipReference* target : targets) {
    if (target->ppd_ != targets.front()->ppd_ || target->planes_.width != t.width ||
        target->planes_.height != t.height)
      throw std::invalid_argument("meanFlips: targets of different sizes or viewing conditions");
    flipCombineFast(t, target->planes_, map.data());
    means.push_back(meanOf(map));
  }
  return means;
}

// (FlipReference checks the sizes.)
std::vector<float> flipMap(const Image& test, const Image& reference, double ppd) {
  return FlipReference(reference, ppd).map(test);
}

double meanFlip(const Image& test, const Image& reference, double ppd) { return FlipReference(reference, ppd).mean(test); }

}  // namespace aliaslab
