#include "core/huge_pages.h"

#include <malloc.h>
#include <sys/mman.h>

#include <cstdlib>
#include <map>
#include <mutex>

namespace aliaslab {

namespace {
constexpr size_t kHugePage = size_t(2) << 20;
constexpr size_t kPoolCap = size_t(512) << 20;  ///< freed large blocks kept for reuse, at most 512 MiB

// Freed large blocks by size. A sweep allocates the same few sizes over and over (a sample set, an
// Accumulator's sums); handing a block back instead of returning it to the kernel saves its page faults
// and, more costly, the munmap, whose TLB shootdown stalls every other thread of the process. One mutex,
// taken once per large allocation or free (a few per sample set), never per sample.
struct Pool {
  std::mutex mutex;
  std::multimap<size_t, void*> blocks;
  size_t pooled = 0;
};
Pool& pool() {
  static Pool* p = new Pool;  // never destroyed: blocks may be freed during static destruction
  return *p;
}
}  // namespace

void* allocateLarge(size_t bytes) {
  if (bytes < kHugePage) {
    if (void* p = std::malloc(bytes == 0 ? 1 : bytes)) return p;
    throw std::bad_alloc();
  }
  const size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  Pool& P = pool();
  {
    std::lock_guard lock(P.mutex);
    if (auto it = P.blocks.find(rounded); it != P.blocks.end()) {
      void* p = it->second;
      P.blocks.erase(it);
      P.pooled -= rounded;
      return p;
    }
  }
  void* p = std::aligned_alloc(kHugePage, rounded);
  if (!p) throw std::bad_alloc();
  ::madvise(p, rounded, MADV_HUGEPAGE);  // advice only: ignored where huge pages are off
  return p;
}

void keepMediumBlocks() {
  static const bool done = [] {
    ::mallopt(M_MMAP_THRESHOLD, 32 << 20);   // below 32 MB: from the heap, not a fresh mapping
    ::mallopt(M_TRIM_THRESHOLD, 512 << 20);  // the heap's free top is returned only beyond 512 MB
    return true;
  }();
  (void)done;
}

void freeLarge(void* p, size_t bytes) noexcept {
  if (!p) return;
#if !defined(__SANITIZE_ADDRESS__)  // under AddressSanitizer every block goes back, so use-after-free is caught
  if (bytes >= kHugePage) {
    const size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    Pool& P = pool();
    std::lock_guard lock(P.mutex);
    if (P.pooled + rounded <= kPoolCap) {
      P.blocks.emplace(rounded, p);
      P.pooled += rounded;
      return;
    }
  }
#endif
  std::free(p);
}

}  // namespace aliaslab
