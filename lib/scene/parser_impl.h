// Private to the scene parser: the recursive-descent parser over a token
// stream (parser_tokens.h). parse() first finds the top-level blocks (any
// order, each at most once) and then parses them in dependency order:
// camera, Background, Lights, Materials, Group, so that MaterialIndex can be
// checked against the material count wherever the Materials block sits.
//
// Material state follows the classic course parser: `MaterialIndex k` sets
// the current material for every later object in file order, including
// objects after the enclosing Group closes. Objects before any
// MaterialIndex get material 0 (an error when the scene has no materials).
#pragma once
#include <memory>
#include <string>

#include "scene/parser_tokens.h"
#include "scene/scene.h"

namespace aliaslab::detail {

/// Deepest nesting of Group / Transform blocks accepted (guards the stack).
inline constexpr int kMaxNesting = 256;
/// Procedural materials blend two earlier ones, which may blend others: at most 256 levels of such nesting,
/// and at most 65536 Phong evaluations behind one shading query (a chain of materials that each blend the
/// previous one twice doubles the work per level: 30 levels would be 2^30 evaluations per hit).
inline constexpr int kMaxMaterialNesting = 256;
inline constexpr double kMaxMaterialEvaluations = 65536;

class SceneParser {
 public:
  SceneParser(TokenStream& tokens, Scene& scene, std::string baseDir)
      : t_(tokens), scene_(scene), baseDir_(std::move(baseDir)) {}
  void parse();

 private:
  // Top level (parser.cpp).
  void parseCamera(const std::string& kind);
  void parseBackground();
  void parseLights();
  // Materials (parser_materials.cpp).
  void parseMaterials();
  std::unique_ptr<Material> parseMaterial(const Token& keyword, int index);
  std::unique_ptr<Material> parseProcedural(const Token& keyword, int index);
  /// A procedural material's optional texture-space Transform { ... } (identity without one).
  Mat4 parseTextureTransform(const std::string& kind);
  /// Its two earlier materials (materialIndex k < index), within the nesting and evaluation limits.
  void parseBlendedMaterials(const Token& keyword, int index, const Material* blend[2]);
  // Objects and transforms (parser_objects.cpp).
  std::unique_ptr<Group> parseGroup(int depth);
  std::unique_ptr<Object> parseObject(int depth);
  std::unique_ptr<Object> parseTransform(const Token& keyword, int depth);
  std::unique_ptr<Object> parseMesh(const Token& keyword);
  /// Consumes one transform op if the next token is one and right-multiplies it into m.
  bool parseTransformOp(Mat4& m);
  const Material* currentMaterial(const Token& object) const;

  TokenStream& t_;
  Scene& scene_;
  std::string baseDir_;
  int current_ = -1;  ///< current MaterialIndex, -1 before the first one
  std::vector<int> materialDepth_;       ///< nesting level of each material (Phong: 1)
  std::vector<double> materialCost_;     ///< Phong evaluations behind one query of each material
};

}  // namespace aliaslab::detail
