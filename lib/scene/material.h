// Materials: how a surface point responds to light.
//
// The tracer asks a material, at a world-space hit point p (a SurfacePoint:
// the point and, when pre-filtering is on, its pixel footprint) with unit shading
// normal n (already flipped towards the viewer when -shade_back applies):
//   shade()       direct diffuse + specular light from one light,
//   diffuse()     the colour the ambient light multiplies,
//   reflective(), transparent(), indexOfRefraction()  for secondary rays.
// Procedural materials blend two earlier materials point by point: each
// query returns a * first + b * second with the pattern's weights (a, b),
// a + b = 1, so nested procedurals compose. Which material a formula's w
// goes to is stated per pattern below (the course gives it to the FIRST
// material in Noise and Marble).
#pragma once
#include <memory>
#include <string>

#include "core/math.h"

namespace aliaslab {

/// A world-space point a material is queried at, with its footprint: the
/// surface covered by one pixel is taken to be the parallelogram
/// p + a dpdx + b dpdy, a, b in [-1/2, 1/2] (ray differentials; see
/// docs/prefiltering.md). Both axes zero (the default, and every query when
/// pre-filtering is off) mean a point sample: materials then evaluate exactly
/// the unfiltered formulas. A Vec3 converts implicitly to a point sample.
struct SurfacePoint {
  Vec3 p = Vec3::Zero();
  Vec3 dpdx = Vec3::Zero(), dpdy = Vec3::Zero();
  SurfacePoint() = default;
  template <class Derived>  // NOLINTNEXTLINE: implicit on purpose (any 3-vector is a point sample)
  SurfacePoint(const Eigen::MatrixBase<Derived>& point) : p(point) {}
  SurfacePoint(const Vec3& point, const Vec3& dx, const Vec3& dy) : p(point), dpdx(dx), dpdy(dy) {}
  bool hasFootprint() const { return !(dpdx.isZero(0.f) && dpdy.isZero(0.f)); }
};
class MaterialAt;

class Material {
 public:
  virtual ~Material() = default;
  /// Diffuse + specular response to light of colour `lightColor` arriving
  /// from unit direction `toLight`; `toViewer` is the unit direction back
  /// along the incoming ray.
  virtual Color shade(const SurfacePoint& p, const Vec3& n, const Vec3& toViewer, const Vec3& toLight,
                      const Color& lightColor) const = 0;
  virtual Color diffuse(const SurfacePoint& p) const = 0;
  virtual Color reflective(const SurfacePoint& p) const = 0;
  virtual Color transparent(const SurfacePoint& p) const = 0;
  virtual float indexOfRefraction(const SurfacePoint& p) const = 0;
  /// One line: kind and parameters; procedurals include their two materials.
  virtual std::string describe() const = 0;
  /// Appends this material's evaluation at p to `out` (see MaterialAt): a
  /// leaf appends itself; a procedural blend appends its weights (a, b) of
  /// its first and second material at p (footprint included), then the
  /// materials they select (first only when b <= 0, second only when a <= 0,
  /// else both).
  virtual void resolve(const SurfacePoint& p, MaterialAt& out) const;
};

/// A material evaluated once at a hit point p: what the tracer queries.
/// Construction walks the procedural blend tree once, computing each blend
/// weight a single time; every query then combines the leaf materials'
/// answers with exactly the arithmetic the blends' own queries use,
/// a * first + b * second with pure ends passing one side through, so
/// each answer is bit-identical to asking the material directly. Trees with
/// more than kMaxNodes evaluated nodes fall back to the direct queries.
class MaterialAt {
 public:
  MaterialAt(const Material& m, const SurfacePoint& p);
  Color shade(const Vec3& n, const Vec3& toViewer, const Vec3& toLight, const Color& lightColor) const;
  Color diffuse() const;
  Color reflective() const;
  Color transparent() const;
  float indexOfRefraction() const;

  /// For Material::resolve: a leaf material, or a blend node followed by its selected materials.
  void appendLeaf(const Material* leaf);
  void appendBlend(float first, float second);

 private:
  static constexpr int kMaxNodes = 32;
  struct Node {
    const Material* leaf;  ///< nullptr: a blend node with these weights of its two materials
    float first, second;
  };
  template <class Query>
  auto evaluate(Query query) const;
  template <class Query>
  auto evaluate(int& i, Query query) const;

  const Material* material_;
  SurfacePoint p_;
  Node nodes_[kMaxNodes];
  int count_ = 0;
  bool overflow_ = false;
};

/// PhongMaterial (alias Material). Blinn-Phong: for n.l > 0,
///   shade = lightColor * (diffuse * (n.l) + specular * max(0, n.h)^exponent),
/// h = normalize(toLight + toViewer); zero when n.l <= 0.
struct PhongParams {
  Color diffuse = Color::Ones();         ///< diffuseColor, default 1 1 1
  Color specular = Color::Zero();        ///< specularColor, default 0
  float exponent = 1.f;                  ///< exponent, default 1
  Color reflective = Color::Zero();      ///< reflectiveColor, default 0
  Color transparent = Color::Zero();     ///< transparentColor, default 0
  float indexOfRefraction = 1.f;         ///< default 1
};
std::unique_ptr<Material> makePhong(const PhongParams& params);

/// Checkerboard: unit cells in texture space (textureFromWorld * p),
/// `first` where floor(x)+floor(y)+floor(z) is even, else `second`.
std::unique_ptr<Material> makeCheckerboard(const Mat4& textureFromWorld, const Material* first,
                                           const Material* second);

/// Noise (the course's formula): T(q) = sum_{k<octaves} noise(2^k q) / 2^k,
/// q = textureFromWorld * p, noise = Perlin's improved noise (2002);
/// w = clamp(T + 0.5, 0, 1) and the colour is w * first + (1 - w) * second.
std::unique_ptr<Material> makeNoise(const Mat4& textureFromWorld, const Material* first,
                                    const Material* second, int octaves);

/// Marble (the course's formula): w = (sin(frequency * q.x + amplitude * T(q)) + 1) / 2,
/// T as for Noise (no offset); the colour is w * first + (1 - w) * second.
std::unique_ptr<Material> makeMarble(const Mat4& textureFromWorld, const Material* first,
                                     const Material* second, int octaves, float frequency,
                                     float amplitude);

/// Wood (the course left it open; aliaslab's choice): rings around the
/// texture-space y axis, w = 0.5 + 0.5 * sin(frequency * sqrt(q.x^2 + q.z^2) + amplitude * T(q)),
/// colour (1 - w) * first + w * second.
std::unique_ptr<Material> makeWood(const Mat4& textureFromWorld, const Material* first,
                                   const Material* second, int octaves, float frequency,
                                   float amplitude);

/// aliaslab extension for analytic aliasing test patterns, evaluated on
/// texture-space (x, y), colour (1 - w) * first + w * second:
///   zoneplate  w = 0.5 + 0.5 * sin(frequency * (x^2 + y^2))
///   sinc       w = 0.5 + 0.5 * sinc(frequency x) * sinc(frequency y), sinc(t) = sin(pi t)/(pi t)
///   siemens    w = 1 when sin(frequency * atan2(y, x)) >= 0 else 0 (frequency = number of spoke pairs)
///   stripes    w = 1 when sin(2 pi frequency x) >= 0 else 0
///   grating    w = 0.5 + 0.5 * cos(2 pi frequency (x cos a + y sin a)), a = angleDegrees (only the grating uses it)
enum class PatternKind { ZonePlate, Sinc, Siemens, Stripes, Grating };
std::unique_ptr<Material> makePattern(const Mat4& textureFromWorld, const Material* first,
                                      const Material* second, PatternKind kind, float frequency,
                                      float angleDegrees = 0.f);

/// Perlin's improved noise (2002) with his published permutation; in about [-1, 1].
float perlinNoise(float x, float y, float z);

}  // namespace aliaslab
