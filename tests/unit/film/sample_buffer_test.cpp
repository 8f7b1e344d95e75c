// The sample buffer's memory: large buffers from core/huge_pages.h, and the variable-count layout.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "core/huge_pages.h"
#include "film/film.h"

// Large sample buffers and sums come from core/huge_pages.h: 2 MB-aligned, and a freed block is handed out
// again for the same size (not under AddressSanitizer, which must see every free).
TEST(LargeBuffers, AlignedAndReusedForTheSameSize) {
  const size_t bytes = (size_t(5) << 20) + 123;  // rounds up to 6 MB
  void* a = aliaslab::allocateLarge(bytes);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(a) % (size_t(2) << 20), 0u);
  std::memset(a, 0x5a, bytes);  // the whole block is usable
  aliaslab::freeLarge(a, bytes);
  void* b = aliaslab::allocateLarge((size_t(6) << 20) - 7);  // same rounded size
#if defined(__SANITIZE_ADDRESS__)
  (void)b;
#else
  EXPECT_EQ(b, a);
#endif
  aliaslab::freeLarge(b, (size_t(6) << 20) - 7);
  // small blocks are plain malloc; a SampleBuffer's vector still starts value-initialised when reused
  void* s = aliaslab::allocateLarge(100);
  ASSERT_NE(s, nullptr);
  aliaslab::freeLarge(s, 100);
  for (int round = 0; round < 2; ++round) {
    aliaslab::SampleBuffer buf(512, 256, 16);  // 50 MB
    for (const aliaslab::FilmSample& f : buf.samples()) ASSERT_TRUE(f.x == 0 && f.y == 0 && f.weight == 1.f);
    for (aliaslab::FilmSample& f : buf.samples()) f.x = f.y = 7.f, f.weight = 3.f;
  }
}

// The variable-count buffer without the fill (SampleBuffer::Unwritten, for a caller that writes every sample:
// the adaptive gather) has the same layout as the filled one: counts, row counts and each pixel's first sample
// at the same offset (the prefix sums of the counts, summed here), and refuses the same bad counts. The filled
// one still starts as FilmSample{} in large memory that a previous buffer of the same size left dirty.
TEST(LargeBuffers, VariableCountUnwrittenHasTheFilledLayout) {
  using aliaslab::SampleBuffer;
  const int w = 300, h = 200;
  std::vector<int> counts(w * h);
  for (int p = 0; p < w * h; ++p) counts[p] = (p * 7919) % 23;  // 0 .. 22, zeros included
  for (int round = 0; round < 2; ++round) {
    SampleBuffer filled(w, h, counts), bare(w, h, counts, SampleBuffer::Unwritten{});
    ASSERT_EQ(bare.samples().size(), filled.samples().size());
    EXPECT_TRUE(bare.variable());
    size_t offset = 0;
    for (int j = 0; j < h; ++j) {
      size_t row = 0;
      for (int i = 0; i < w; ++i) {
        const int n = counts[size_t(j) * w + i];
        ASSERT_EQ(bare.count(i, j), n);
        ASSERT_EQ(bare.pixel(i, j) - bare.samples().data(), std::ptrdiff_t(offset));
        ASSERT_EQ(filled.pixel(i, j) - filled.samples().data(), std::ptrdiff_t(offset));
        offset += n, row += n;
      }
      ASSERT_EQ(bare.rowCount(j), row);
    }
    EXPECT_EQ(offset, bare.samples().size());
    for (const aliaslab::FilmSample& f : filled.samples()) ASSERT_TRUE(f.x == 0 && f.y == 0 && f.weight == 1.f);
    for (aliaslab::FilmSample& f : filled.samples()) f.x = f.y = 7.f, f.weight = 3.f;
    for (aliaslab::FilmSample& f : bare.samples()) f.x = f.y = 5.f, f.weight = 2.f;
  }
  EXPECT_THROW(SampleBuffer(2, 2, std::vector<int>(3, 1), SampleBuffer::Unwritten{}), std::invalid_argument);
  EXPECT_THROW(SampleBuffer(1, 2, std::vector<int>{1, -1}, SampleBuffer::Unwritten{}), std::invalid_argument);
}
