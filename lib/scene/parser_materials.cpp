// Scene file parser: the Materials block (Phong and procedural materials).
#include "scene/parser_fields.h"
#include "scene/parser_impl.h"

#include <algorithm>
#include <cmath>

#include "core/format.h"

namespace aliaslab::detail {

namespace {
// The largest |frequency| of a Marble, Wood or Pattern (see the pattern fields below).
constexpr float kMaxPatternFrequency = 1e6f;
}  // namespace

void SceneParser::parseMaterials() {
  t_.expect("{", "after 'Materials'");
  t_.expect("numMaterials", "at the start of Materials");
  const int n = t_.integer("numMaterials", 0, 1 << 30);
  for (;;) {
    const Token& k = t_.next("a material or '}'");
    const int count = static_cast<int>(scene_.materials.size());
    if (k.text == "}") {
      if (count < n)
        t_.fail(k.line, "Materials: numMaterials is " + std::to_string(n) + " but only " + std::to_string(count) +
                            " materials are given before '}'");
      return;
    }
    static const char* kinds[] = {"PhongMaterial", "Material", "Checkerboard", "Noise", "Marble", "Wood", "Pattern"};
    bool known = false;
    for (const char* kind : kinds) known = known || k.text == kind;
    if (!known)
      t_.fail(k.line, "unknown keyword " + TokenStream::describe(k) +
                          " in Materials: expected PhongMaterial, Material, Checkerboard, Noise, Marble, Wood, "
                          "Pattern or '}'");
    if (count == n)
      t_.fail(k.line, "Materials: more materials than numMaterials " + std::to_string(n) + ": found an extra '" +
                          k.text + "'");
    scene_.materials.push_back(parseMaterial(k, count));
  }
}

std::unique_ptr<Material> SceneParser::parseMaterial(const Token& keyword, int index) {
  t_.expect("{", "after '" + keyword.text + "'");
  if (keyword.text != "PhongMaterial" && keyword.text != "Material") return parseProcedural(keyword, index);

  // Phong: every field optional, any order.
  FieldBlock f(t_, keyword.text,
               {{"diffuseColor", FieldKind::Vec3},
                {"specularColor", FieldKind::Vec3},
                {"exponent"},
                {"reflectiveColor", FieldKind::Vec3},
                {"transparentColor", FieldKind::Vec3},
                {"indexOfRefraction"}});
  PhongParams p;
  p.diffuse = f.vec3("diffuseColor", p.diffuse.matrix()).array();
  p.specular = f.vec3("specularColor", p.specular.matrix()).array();
  p.exponent = f.number("exponent", p.exponent);
  p.reflective = f.vec3("reflectiveColor", p.reflective.matrix()).array();
  p.transparent = f.vec3("transparentColor", p.transparent.matrix()).array();
  p.indexOfRefraction = f.number("indexOfRefraction", p.indexOfRefraction);
  if (p.exponent < 0.f) f.fail("exponent", "must not be negative");
  if (!(p.indexOfRefraction > 0.f)) f.fail("indexOfRefraction", "must be positive");
  materialDepth_.resize(static_cast<size_t>(index) + 1, 1), materialDepth_[index] = 1;
  materialCost_.resize(static_cast<size_t>(index) + 1, 1), materialCost_[index] = 1;
  return makePhong(p);
}

Mat4 SceneParser::parseTextureTransform(const std::string& kind) {
  // q = M p with M = op1 * op2 * ...
  Mat4 m = Mat4::Identity();
  if (t_.peek().text == "Transform") {
    t_.next("Transform");
    t_.expect("{", "after 'Transform'");
    while (parseTransformOp(m)) {}
    const Token& close = t_.next("'}' closing the Transform of " + kind);
    if (close.text != "}")
      t_.fail(close.line, "expected a transform op (Scale, UniformScale, Translate, XRotate, YRotate, ZRotate, "
                          "Rotate, Matrix) or '}' in the Transform of " + kind + ", found " +
                              TokenStream::describe(close));
  }
  return m;
}

void SceneParser::parseBlendedMaterials(const Token& keyword, int index, const Material* blend[2]) {
  const std::string& kind = keyword.text;
  int depth = 1;
  double cost = 0;
  for (int e = 0; e < 2; ++e) {
    t_.expect("materialIndex", "in " + kind);
    const int line = t_.peek().line;
    const int k = t_.integer("materialIndex", -(1 << 30), 1 << 30);
    if (k < 0 || k >= index)
      t_.fail(line, kind + " (material " + std::to_string(index) + "): materialIndex " + std::to_string(k) +
                        (index == 0 ? " is invalid: a procedural material needs two earlier materials"
                                    : " must refer to an earlier material (0.." + std::to_string(index - 1) + ")"));
    blend[e] = scene_.materials[k].get();
    depth = std::max(depth, 1 + materialDepth_.at(k));
    cost += materialCost_.at(k);
  }
  if (depth > kMaxMaterialNesting)
    t_.fail(keyword.line, kind + " (material " + std::to_string(index) + "): materials nested deeper than " +
                              std::to_string(kMaxMaterialNesting) + " levels (each blends earlier materials)");
  if (cost > kMaxMaterialEvaluations)
    t_.fail(keyword.line, kind + " (material " + std::to_string(index) + "): one query would evaluate " +
                              formatNumber(cost, "%.0f") + " Phong materials (the limit is " +
                              formatNumber(kMaxMaterialEvaluations, "%.0f") +
                              "): blending the same nested material twice doubles the work per level");
  materialDepth_.resize(static_cast<size_t>(index) + 1, 1), materialDepth_[index] = depth;
  materialCost_.resize(static_cast<size_t>(index) + 1, 1), materialCost_[index] = cost;
}

std::unique_ptr<Material> SceneParser::parseProcedural(const Token& keyword, int index) {
  const std::string& kind = keyword.text;
  const Mat4 m = parseTextureTransform(kind);
  const Material* blend[2];
  parseBlendedMaterials(keyword, index, blend);

  // The pattern's own fields. A frequency multiplies texture coordinates into a phase: beyond 1e6 a float phase
  // keeps no digit of its fraction (and near 3e38 it overflows to infinity, every pixel NaN).
  const FieldSpec octaves{"octaves", FieldKind::Integer, 0, 32};
  auto frequency = [](const FieldBlock& f) {
    const float v = f.number("frequency");
    if (!(std::abs(v) <= kMaxPatternFrequency))
      f.fail("frequency", "must be at most " + formatNumber(kMaxPatternFrequency) + " in magnitude (a float phase "
                          "beyond it keeps no digit of its fraction), found " + formatNumber(v));
    return v;
  };
  if (kind == "Checkerboard") {
    FieldBlock f(t_, kind, {});
    return makeCheckerboard(m, blend[0], blend[1]);
  }
  if (kind == "Noise") {
    FieldBlock f(t_, kind, {octaves});
    f.require({"octaves"});
    return makeNoise(m, blend[0], blend[1], f.integer("octaves"));
  }
  if (kind == "Marble" || kind == "Wood") {
    FieldBlock f(t_, kind, {octaves, {"frequency"}, {"amplitude"}});
    f.require({"octaves", "frequency", "amplitude"});
    const int o = f.integer("octaves");
    const float fr = frequency(f), a = f.number("amplitude");
    return kind == "Marble" ? makeMarble(m, blend[0], blend[1], o, fr, a) : makeWood(m, blend[0], blend[1], o, fr, a);
  }
  // Pattern (aliaslab extension).
  FieldBlock f(t_, kind, {{"type", FieldKind::Word}, {"frequency"}, {"angle"}});
  f.require({"type", "frequency"});
  const std::string type = f.word("type");
  PatternKind pk;
  if (type == "zoneplate") pk = PatternKind::ZonePlate;
  else if (type == "sinc") pk = PatternKind::Sinc;
  else if (type == "siemens") pk = PatternKind::Siemens;
  else if (type == "stripes") pk = PatternKind::Stripes;
  else if (type == "grating") pk = PatternKind::Grating;
  else f.fail("type", "must be zoneplate, sinc, siemens, stripes or grating, found '" + type + "'");
  if (pk != PatternKind::Grating && f.has("angle")) f.fail("angle", "is a key of the grating only");
  return makePattern(m, blend[0], blend[1], pk, frequency(f), f.number("angle", 0.f));
}

}  // namespace aliaslab::detail
