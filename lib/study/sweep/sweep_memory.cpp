#include "study/sweep/sweep_memory.h"

#include <algorithm>

#include "core/parallel.h"
#include "film/film.h"

namespace aliaslab {

size_t sweepMemoryBound(int threads, int width, int height, int spp, size_t rowsPerGroup, size_t weightedRows,
                        int seeds) {
  const size_t W = size_t(std::max(1, std::min(seeds, resolveThreads(threads))));
  const size_t T = size_t(resolveThreads(threads));
  const size_t pixels = size_t(width) * height;
  const size_t buffer = pixels * spp * sizeof(FilmSample);
  const size_t accumulator = pixels * (weightedRows + 1) * 4 * sizeof(double);
  // W sample sets with their accumulators, W x rows images, and up to `threads` importance traces at once
  return W * (buffer + accumulator + rowsPerGroup * imageBytes(width, height)) + T * buffer;
}

}  // namespace aliaslab
