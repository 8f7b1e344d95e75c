#include "render/render_image.h"

#include <cmath>

namespace aliaslab {

RenderedImage renderImage(const Tracer& tracer, const SampleSource& source, const Filter* filter, ReconMode mode,
                          int width, int height, int threads, const Progress& progress) {
  RenderedImage out;
  const bool importance = filter && mode == ReconMode::ImportanceSampled;
  out.samples = importance ? source.traceImportance(tracer, *filter, width, height, threads, progress)
                           : source.trace(tracer, width, height, threads, progress);
  for (const FilmSample& s : out.samples.samples())
    if (!std::isfinite(s.L[0]) || !std::isfinite(s.L[1]) || !std::isfinite(s.L[2])) ++out.nonFiniteSamples;
  if (filter) {
    out.image = reconstruct(out.samples, *filter, mode, threads).image;
  } else {
    out.image = Image(width, height);
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) out.image.set(i, j, out.samples.pixel(i, j)[0].L);
  }
  return out;
}

}  // namespace aliaslab
