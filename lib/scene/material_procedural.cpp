// Procedural materials: a blend weight w(q) over texture space q, applied
// to every query of the two blended materials alike.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "scene/material.h"

namespace aliaslab {
namespace {

/// (1 - w) * first + w * second for every query; w in [0, 1] from weight().
class Blend : public Material {
 public:
  Blend(const Mat4& textureFromWorld, const Material* first, const Material* second)
      : textureFromWorld_(textureFromWorld), first_(first), second_(second) {
    if (!first || !second) throw std::invalid_argument("procedural material: both blended materials are required");
  }

 private:
  // Pure ends skip the other material entirely (checkerboards, clamped noise).
  template <class Query>
  auto mix(const Vec3& p, Query query) const {
    const Vec3 q = (textureFromWorld_ * p.homogeneous()).hnormalized();
    const float w = weight(q);
    if (w <= 0.f) return query(first_);
    if (w >= 1.f) return query(second_);
    return decltype(query(first_))((1.f - w) * query(first_) + w * query(second_));
  }

 public:
  Color shade(const Vec3& p, const Vec3& n, const Vec3& toViewer, const Vec3& toLight,
              const Color& lightColor) const override {
    return mix(p, [&](const Material* m) { return m->shade(p, n, toViewer, toLight, lightColor); });
  }
  Color diffuse(const Vec3& p) const override {
    return mix(p, [&](const Material* m) { return m->diffuse(p); });
  }
  Color reflective(const Vec3& p) const override {
    return mix(p, [&](const Material* m) { return m->reflective(p); });
  }
  Color transparent(const Vec3& p) const override {
    return mix(p, [&](const Material* m) { return m->transparent(p); });
  }
  float indexOfRefraction(const Vec3& p) const override {
    return mix(p, [&](const Material* m) { return m->indexOfRefraction(p); });
  }
  void resolve(const Vec3& p, MaterialAt& out) const override {
    const Vec3 q = (textureFromWorld_ * p.homogeneous()).hnormalized();
    const float w = weight(q);
    out.appendBlend(w);
    if (w <= 0.f) {
      first_->resolve(p, out);
    } else if (w >= 1.f) {
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
  /// Blend weight of the second material at texture-space point q.
  virtual float weight(const Vec3& q) const = 0;
  /// The pattern's name and parameters.
  virtual std::string pattern() const = 0;

 private:
  Mat4 textureFromWorld_;
  const Material* first_;
  const Material* second_;
};

/// N(q) = sum_{k<octaves} noise(2^k q) / 2^k.
float turbulence(const Vec3& q, int octaves) {
  float sum = 0.f, scale = 1.f;
  for (int k = 0; k < octaves; ++k, scale *= 2.f)
    sum += perlinNoise(scale * q.x(), scale * q.y(), scale * q.z()) / scale;
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
  float weight(const Vec3& q) const override {
    const long s = std::lround(std::floor(q.x()) + std::floor(q.y()) + std::floor(q.z()));
    return (s & 1) ? 1.f : 0.f;
  }
  std::string pattern() const override { return "checkerboard"; }
};

class Noise final : public Blend {
 public:
  Noise(const Mat4& m, const Material* a, const Material* b, int octaves) : Blend(m, a, b), octaves_(octaves) {}
  float weight(const Vec3& q) const override { return std::clamp(turbulence(q, octaves_), 0.f, 1.f); }
  std::string pattern() const override { return "noise octaves " + std::to_string(octaves_); }

 private:
  int octaves_;
};

class Marble final : public Blend {
 public:
  Marble(const Mat4& m, const Material* a, const Material* b, int octaves, float frequency, float amplitude)
      : Blend(m, a, b), octaves_(octaves), frequency_(frequency), amplitude_(amplitude) {}
  float weight(const Vec3& q) const override {
    return 0.5f + 0.5f * std::sin(frequency_ * q.x() + amplitude_ * turbulence(q, octaves_));
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
  float weight(const Vec3& q) const override {
    const float r = std::sqrt(q.x() * q.x() + q.z() * q.z());
    return 0.5f + 0.5f * std::sin(frequency_ * r + amplitude_ * turbulence(q, octaves_));
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
  Pattern(const Mat4& m, const Material* a, const Material* b, PatternKind kind, float frequency)
      : Blend(m, a, b), kind_(kind), frequency_(frequency) {}
  float weight(const Vec3& q) const override {
    const float x = q.x(), y = q.y();
    switch (kind_) {
      case PatternKind::ZonePlate: return 0.5f + 0.5f * std::sin(frequency_ * (x * x + y * y));
      case PatternKind::Sinc: return 0.5f + 0.5f * sinc(frequency_ * x) * sinc(frequency_ * y);
      case PatternKind::Siemens: return std::sin(frequency_ * std::atan2(y, x)) >= 0.f ? 1.f : 0.f;
      case PatternKind::Stripes: return std::sin(2.f * kPi * frequency_ * x) >= 0.f ? 1.f : 0.f;
    }
    return 0.f;
  }
  std::string pattern() const override {
    static const char* names[] = {"zoneplate", "sinc", "siemens", "stripes"};
    return std::string(names[static_cast<int>(kind_)]) + " frequency " + number(frequency_);
  }

 private:
  PatternKind kind_;
  float frequency_;
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
                                      const Material* second, PatternKind kind, float frequency) {
  return std::make_unique<Pattern>(textureFromWorld, first, second, kind, frequency);
}

}  // namespace aliaslab
