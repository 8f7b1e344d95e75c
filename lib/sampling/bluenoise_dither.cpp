// bluenoise-dither:BASE: one BASE point set per seed, shifted per pixel by a
// blue-noise mask (Georgiev and Fajardo 2016; Heitz and Belcour 2019).
//
// | property   | value                                                      |
// |------------|------------------------------------------------------------|
// | points     | the base sampler's points of pixel (0, 0) for this seed,   |
// |            | the same set in every pixel, each shifted toroidally       |
// |            | (Cranley-Patterson) by the pixel's shift (sx, sy): 32-bit  |
// |            | fixed-point add with wrap-around                           |
// | shift      | sx = rank_x(px mod 64, py mod 64) / 4096 + ux (mod 1), sy  |
// |            | likewise from a second mask: rank_x, rank_y are two        |
// |            | void-and-cluster masks (bluenoise_mask.h) of the seed, one |
// |            | per coordinate of the dimension pair (this tracer samples  |
// |            | one pair, the sub-pixel position); (ux, uy) is a uniform   |
// |            | offset of the seed, so every pixel's shift is exactly      |
// |            | uniform over seeds and the estimate stays unbiased         |
// | why shared | dithering only moves error to high frequencies if the      |
// |            | pixels share the pattern: then neighbouring pixels see the |
// |            | same integrand error function at shifts that differ as     |
// |            | much as possible, and their errors anti-correlate. A base  |
// |            | that draws each pixel independently (its own per-pixel     |
// |            | decorrelation) is therefore replaced, not kept             |
// | counts     | those of the base (its warning() is passed on)             |
// | bases      | any plain registered name; a wrapper of a wrapper is       |
// |            | refused by the factory                                     |
// | use it     | to see what blue-noise error distribution buys at equal    |
// |            | mse (lowfreq_error, blurred_mse in the study CSV).         |
#include <array>
#include <vector>

#include "core/hash.h"
#include "sampling/bluenoise_mask.h"
#include "sampling/sample_math.h"
#include "sampling/sampler_registry.h"

namespace aliaslab::sampling {
namespace {

/// float in [0,1) to 32-bit fixed point (truncated; exact for the samplers' 24-bit fixed-point values).
inline uint32_t unitToFixed(float v) { return static_cast<uint32_t>(static_cast<double>(v) * 0x1p32); }

class BlueNoiseDitherSampler final : public Sampler {
 public:
  BlueNoiseDitherSampler(std::unique_ptr<Sampler> base, uint64_t seed)
      : Sampler(base->spp(), seed),
        base_(std::move(base)),
        maskX_(blueNoiseMask(seed, 0)),
        maskY_(blueNoiseMask(seed, 1)) {
    std::vector<Vec2> pts(spp());
    base_->generate(0, 0, pts.data());
    for (const Vec2& v : pts) pattern_.push_back({unitToFixed(v.x()), unitToFixed(v.y())});
    const uint64_t h = hashWords(seed, 0x646974686572ULL);
    offsetX_ = key32(h), offsetY_ = static_cast<uint32_t>(h);
  }

  void generate(int px, int py, Vec2* out) const override {
    const size_t cell = static_cast<size_t>(py & (kMaskSize - 1)) * kMaskSize + (px & (kMaskSize - 1));
    // rank * 2^32 / 4096, i.e. the rank in the top 12 bits
    const uint32_t sx = (static_cast<uint32_t>((*maskX_)[cell]) << 20) + offsetX_;
    const uint32_t sy = (static_cast<uint32_t>((*maskY_)[cell]) << 20) + offsetY_;
    for (size_t i = 0; i < pattern_.size(); ++i)
      out[i] = Vec2(fixedToUnit(pattern_[i][0] + sx), fixedToUnit(pattern_[i][1] + sy));
  }
  std::string name() const override { return "bluenoise-dither:" + base_->name(); }
  std::string describe() const override {
    return "bluenoise-dither (64x64 void-and-cluster shift per pixel) of one " + base_->describe() + " set";
  }
  std::string warning() const override { return base_->warning(); }
  bool correlatedAcrossPixels() const override { return true; }

 private:
  static_assert(kMaskSize * kMaskSize == 1 << 12, "the shift puts the rank in the top 12 bits");
  std::unique_ptr<Sampler> base_;
  std::shared_ptr<const std::vector<uint16_t>> maskX_, maskY_;
  std::vector<std::array<uint32_t, 2>> pattern_;  ///< the shared set in 32-bit fixed point
  uint32_t offsetX_ = 0, offsetY_ = 0;
};

}  // namespace

std::unique_ptr<Sampler> makeBlueNoiseDitherSampler(std::unique_ptr<Sampler> base, uint64_t seed) {
  return std::make_unique<BlueNoiseDitherSampler>(std::move(base), seed);
}

}  // namespace aliaslab::sampling
