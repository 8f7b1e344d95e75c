// Procedural materials: a blend weight w(q) over texture space q, applied
// to every query of the two blended materials alike. With a footprint
// (pre-filtering) each pattern averages its weight over the footprint
// (scene/prefilter.h); without one it evaluates the point formula.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "scene/material.h"
#include "scene/prefilter.h"

namespace aliaslab {
namespace {

/// a * first + b * second for every query, (a, b) = weights() of the pattern.
class Blend : public Material {
 public:
  Blend(const Mat4& textureFromWorld, const Material* first, const Material* second)
      : textureFromWorld_(textureFromWorld), first_(first), second_(second) {
    if (!first || !second) throw std::invalid_argument("procedural material: both blended materials are required");
  }

 private:
  // The weights at s: the point formula, or averaged over s's footprint.
  auto weightsAt(const SurfacePoint& s) const {  // -> Weights (declared below)
    const Vec4 h = textureFromWorld_ * s.p.homogeneous();
    const Vec3 q = h.hnormalized();
    if (!s.hasFootprint()) return weights(q, nullptr);
    // texture-space footprint: the derivative of q = h.xyz / h.w along each axis
    auto axis = [&](const Vec3& d) {
      const Vec4 dh = textureFromWorld_.leftCols<3>() * d;
      return Vec3((dh.head<3>() - q * dh.w()) / h.w());
    };
    const TextureFootprint fp{axis(s.dpdx), axis(s.dpdy)};
    return weights(q, &fp);
  }

  // Pure ends skip the other material entirely (checkerboards, clamped noise).
  template <class Query>
  auto mix(const SurfacePoint& s, Query query) const {
    const Weights w = weightsAt(s);
    if (w.second <= 0.f) return query(first_);
    if (w.first <= 0.f) return query(second_);
    return decltype(query(first_))(w.first * query(first_) + w.second * query(second_));
  }

 public:
  Color shade(const SurfacePoint& p, const Vec3& n, const Vec3& toViewer, const Vec3& toLight,
              const Color& lightColor) const override {
    return mix(p, [&](const Material* m) { return m->shade(p, n, toViewer, toLight, lightColor); });
  }
  Color diffuse(const SurfacePoint& p) const override {
    return mix(p, [&](const Material* m) { return m->diffuse(p); });
  }
  Color reflective(const SurfacePoint& p) const override {
    return mix(p, [&](const Material* m) { return m->reflective(p); });
  }
  Color transparent(const SurfacePoint& p) const override {
    return mix(p, [&](const Material* m) { return m->transparent(p); });
  }
  float indexOfRefraction(const SurfacePoint& p) const override {
    return mix(p, [&](const Material* m) { return m->indexOfRefraction(p); });
  }
  void resolve(const SurfacePoint& p, MaterialAt& out) const override {  // as mix() selects
    const Weights w = weightsAt(p);
    out.appendBlend(w.first, w.second);
    if (w.second <= 0.f) {
      first_->resolve(p, out);
    } else if (w.first <= 0.f) {
      second_->resolve(p, out);
    } else {
      first_->resolve(p, out);
      second_->resolve(p, out);
    }
  }
  std::string describe() const override {
    return pattern() + (textureFromWorld_.isIdentity() ? "" : " transformed") + " [" + first_->describe() +
           " | " + second_->describe() + "]";
  }

 protected:
  /// Weights of the first and second material (summing to 1).
  struct Weights {
    float first, second;
  };
  /// The weights at texture-space point q: the point formula when `fp` is
  /// null, else the weights averaged over (or band-limited to) the footprint.
  virtual Weights weights(const Vec3& q, const TextureFootprint* fp) const = 0;
  /// Patterns whose formula gives the SECOND material the weight w.
  static Weights toSecond(float w) { return {1.f - w, w}; }
  /// Patterns whose formula gives the FIRST material the weight w (the course's Noise and Marble).
  static Weights toFirst(float w) { return {w, 1.f - w}; }
  /// The pattern's name and parameters.
  virtual std::string pattern() const = 0;

 private:
  Mat4 textureFromWorld_;
  const Material* first_;
  const Material* second_;
};

/// T(q) = sum_{k<octaves} noise(2^k q) / 2^k.
float turbulence(const Vec3& q, int octaves) {
  float sum = 0.f, scale = 1.f;
  for (int k = 0; k < octaves; ++k, scale *= 2.f)
    sum += perlinNoise(scale * q.x(), scale * q.y(), scale * q.z()) / scale;
  return sum;
}

/// T clamped to the footprint width W: octave k (lattice spacing, its
/// wavelength, 2^-k) is weighted by octaveWeight(2^-k, W); dropped octaves
/// contribute their mean, 0. Octaves of weight 1 add exactly what
/// turbulence() adds, so a footprint far below the finest octave gives T.
float turbulence(const Vec3& q, int octaves, float width) {
  float sum = 0.f, scale = 1.f;
  for (int k = 0; k < octaves; ++k, scale *= 2.f) {
    const float c = octaveWeight(1.f / scale, width);
    if (c <= 0.f) break;  // finer octaves are narrower still
    const float n = perlinNoise(scale * q.x(), scale * q.y(), scale * q.z()) / scale;
    sum += c == 1.f ? n : c * n;
  }
  return sum;
}

std::string number(float v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

std::string turbulenceParams(int octaves, float frequency, float amplitude) {
  return " octaves " + std::to_string(octaves) + " frequency " + number(frequency) + " amplitude " + number(amplitude);
}

class Checkerboard final : public Blend {
 public:
  using Blend::Blend;
  Weights weights(const Vec3& q, const TextureFootprint* fp) const override {
    if (fp) {
      // (-1)^(floor x + floor y + floor z) is a product of three 1D signs, so
      // its average over the footprint's bounding box is the product of the
      // three 1D averages (exact); the second material has weight (1 - sign) / 2.
      const Vec3 h = fp->halfWidths();
      const double sign = checkerSignAverage(q.x(), h.x()) * checkerSignAverage(q.y(), h.y()) *
                          checkerSignAverage(q.z(), h.z());
      return toSecond(static_cast<float>(0.5 * (1.0 - sign)));
    }
    const long s = std::lround(std::floor(q.x()) + std::floor(q.y()) + std::floor(q.z()));
    return toSecond((s & 1) ? 1.f : 0.f);
  }
  std::string pattern() const override { return "checkerboard"; }
};

class Noise final : public Blend {
 public:
  Noise(const Mat4& m, const Material* a, const Material* b, int octaves) : Blend(m, a, b), octaves_(octaves) {}
  // The course's formula: w = clamp(T + 0.5, 0, 1) to the FIRST material.
  Weights weights(const Vec3& q, const TextureFootprint* fp) const override {
    const float t = fp ? turbulence(q, octaves_, fp->width()) : turbulence(q, octaves_);
    return toFirst(std::clamp(t + 0.5f, 0.f, 1.f));
  }
  std::string pattern() const override { return "noise octaves " + std::to_string(octaves_); }

 private:
  int octaves_;
};

class Marble final : public Blend {
 public:
  Marble(const Mat4& m, const Material* a, const Material* b, int octaves, float frequency, float amplitude)
      : Blend(m, a, b), octaves_(octaves), frequency_(frequency), amplitude_(amplitude) {}
  // The course's formula: w = (sin(f x + a T) + 1) / 2 to the FIRST material.
  // Pre-filtered: the octaves of T are clamped to the footprint, and the
  // carrier sin(f x) (wavelength 2 pi / f along x) is faded by the same rule
  // with the footprint's extent along x.
  Weights weights(const Vec3& q, const TextureFootprint* fp) const override {
    if (!fp) return toFirst((std::sin(frequency_ * q.x() + amplitude_ * turbulence(q, octaves_)) + 1.f) / 2.f);
    const float carrier = octaveWeight(2.f * kPi / std::abs(frequency_), 2.f * fp->halfWidths().x());
    const float wave = std::sin(frequency_ * q.x() + amplitude_ * turbulence(q, octaves_, fp->width()));
    return toFirst(((carrier == 1.f ? wave : carrier * wave) + 1.f) / 2.f);
  }
  std::string pattern() const override { return "marble" + turbulenceParams(octaves_, frequency_, amplitude_); }

 private:
  int octaves_;
  float frequency_, amplitude_;
};

class Wood final : public Blend {
 public:
  Wood(const Mat4& m, const Material* a, const Material* b, int octaves, float frequency, float amplitude)
      : Blend(m, a, b), octaves_(octaves), frequency_(frequency), amplitude_(amplitude) {}
  // Pre-filtered as Marble, the carrier's wavelength measured along the radius.
  Weights weights(const Vec3& q, const TextureFootprint* fp) const override {
    const float r = std::sqrt(q.x() * q.x() + q.z() * q.z());
    if (!fp) return toSecond(0.5f + 0.5f * std::sin(frequency_ * r + amplitude_ * turbulence(q, octaves_)));
    float radial = fp->width();  // at the axis: any direction is radial
    if (r > 0.f) {
      const Vec3 dir(q.x() / r, 0.f, q.z() / r);
      radial = std::abs(fp->dqdx.dot(dir)) + std::abs(fp->dqdy.dot(dir));
    }
    const float carrier = octaveWeight(2.f * kPi / std::abs(frequency_), radial);
    const float wave = std::sin(frequency_ * r + amplitude_ * turbulence(q, octaves_, fp->width()));
    return toSecond(0.5f + 0.5f * (carrier == 1.f ? wave : carrier * wave));
  }
  std::string pattern() const override { return "wood" + turbulenceParams(octaves_, frequency_, amplitude_); }

 private:
  int octaves_;
  float frequency_, amplitude_;
};

float sinc(float t) {
  if (std::abs(t) < 1e-6f) return 1.f;
  return std::sin(kPi * t) / (kPi * t);
}

class Pattern final : public Blend {
 public:
  Pattern(const Mat4& m, const Material* a, const Material* b, PatternKind kind, float frequency, float angle)
      : Blend(m, a, b), kind_(kind), frequency_(frequency), angle_(angle),
        cos_(static_cast<float>(std::cos(angle * kPi / 180.0))), sin_(static_cast<float>(std::sin(angle * kPi / 180.0))) {}
  Weights weights(const Vec3& q, const TextureFootprint* fp) const override {
    return toSecond(fp ? filteredWeight(q, *fp) : weight(q));
  }
  float weight(const Vec3& q) const {
    const float x = q.x(), y = q.y();
    switch (kind_) {
      case PatternKind::ZonePlate: return 0.5f + 0.5f * std::sin(frequency_ * (x * x + y * y));
      case PatternKind::Sinc: return 0.5f + 0.5f * sinc(frequency_ * x) * sinc(frequency_ * y);
      case PatternKind::Siemens: return std::sin(frequency_ * std::atan2(y, x)) >= 0.f ? 1.f : 0.f;
      case PatternKind::Stripes: return std::sin(2.f * kPi * frequency_ * x) >= 0.f ? 1.f : 0.f;
      case PatternKind::Grating: return 0.5f + 0.5f * std::cos(2.f * kPi * frequency_ * (x * cos_ + y * sin_));
    }
    return 0.f;
  }
  // Box averages over the footprint's bounding box (half-widths hx, hy):
  // stripes, sinc and the grating exactly; the zone plate and the Siemens star through
  // their local frequency (the phase linearised across the box).
  float filteredWeight(const Vec3& q, const TextureFootprint& fp) const {
    const double x = q.x(), y = q.y(), f = frequency_;
    const Vec3 h = fp.halfWidths();
    const double hx = h.x(), hy = h.y();
    switch (kind_) {
      case PatternKind::ZonePlate: {
        // sin(phi) with phi = f (x^2 + y^2): a box of half-widths hx, hy scales a
        // locally linear phase by sinc(phi_x hx) sinc(phi_y hy), phi_x = 2 f x.
        const double phi = f * (x * x + y * y);
        const double a = boxAttenuation(2 * f * x * hx) * boxAttenuation(2 * f * y * hy);
        return static_cast<float>(0.5 + 0.5 * std::sin(phi) * a);
      }
      case PatternKind::Sinc:
        return static_cast<float>(0.5 + 0.5 * sincAverage(f * x, std::abs(f) * hx) *
                                            sincAverage(f * y, std::abs(f) * hy));
      case PatternKind::Siemens: {
        // 1 where frac(u) < 1/2, u = f atan2(y, x) / (2 pi); u's extent over the
        // box from its gradient f (-y, x) / (2 pi r^2).
        const double r2 = x * x + y * y;
        if (!(r2 > 0)) return 0.5f;
        const double u = f * std::atan2(y, x) / (2 * kPi);
        const double hu = std::abs(f) / (2 * kPi * r2) * (std::abs(y) * hx + std::abs(x) * hy);
        return static_cast<float>(squareWaveAverage(u, hu));
      }
      case PatternKind::Stripes:
        return static_cast<float>(squareWaveAverage(f * x, std::abs(f) * hx));
      case PatternKind::Grating: {
        // cos(kx x + ky y) is separable into x and y factors: a box scales it by sinc(kx hx) sinc(ky hy).
        const double kx = 2 * kPi * f * cos_, ky = 2 * kPi * f * sin_;
        return static_cast<float>(0.5 + 0.5 * std::cos(kx * x + ky * y) * boxAttenuation(kx * hx) *
                                            boxAttenuation(ky * hy));
      }
    }
    return 0.f;
  }
  std::string pattern() const override {
    static const char* names[] = {"zoneplate", "sinc", "siemens", "stripes", "grating"};
    return std::string(names[static_cast<int>(kind_)]) + " frequency " + number(frequency_) +
           (kind_ == PatternKind::Grating ? " angle " + number(angle_) : "");
  }

 private:
  PatternKind kind_;
  float frequency_, angle_;
  float cos_, sin_;  ///< of the grating's angle
};

}  // namespace

std::unique_ptr<Material> makeCheckerboard(const Mat4& textureFromWorld, const Material* first,
                                           const Material* second) {
  return std::make_unique<Checkerboard>(textureFromWorld, first, second);
}

std::unique_ptr<Material> makeNoise(const Mat4& textureFromWorld, const Material* first,
                                    const Material* second, int octaves) {
  return std::make_unique<Noise>(textureFromWorld, first, second, octaves);
}

std::unique_ptr<Material> makeMarble(const Mat4& textureFromWorld, const Material* first,
                                     const Material* second, int octaves, float frequency,
                                     float amplitude) {
  return std::make_unique<Marble>(textureFromWorld, first, second, octaves, frequency, amplitude);
}

std::unique_ptr<Material> makeWood(const Mat4& textureFromWorld, const Material* first,
                                   const Material* second, int octaves, float frequency,
                                   float amplitude) {
  return std::make_unique<Wood>(textureFromWorld, first, second, octaves, frequency, amplitude);
}

std::unique_ptr<Material> makePattern(const Mat4& textureFromWorld, const Material* first,
                                      const Material* second, PatternKind kind, float frequency,
                                      float angleDegrees) {
  return std::make_unique<Pattern>(textureFromWorld, first, second, kind, frequency, angleDegrees);
}

}  // namespace aliaslab
