// Scene file parser: groups, primitives, meshes and transforms.
#include <filesystem>

#include "core/error.h"
#include "scene/parser_fields.h"
#include "scene/parser_impl.h"

namespace aliaslab::detail {

namespace {
const char* const kObjectKinds[] = {"Group", "Sphere", "Plane", "Triangle", "TriangleMesh", "Transform"};
bool isObjectKind(const std::string& s) {
  for (const char* k : kObjectKinds)
    if (s == k) return true;
  return false;
}
const char* const kObjectList = "Group, Sphere, Plane, Triangle, TriangleMesh or Transform";
}  // namespace

const Material* SceneParser::currentMaterial(const Token& object) const {
  if (scene_.materials.empty())
    t_.fail(object.line, "'" + object.text + "' needs a material but the scene declares no Materials");
  return scene_.materials[current_ < 0 ? 0 : current_].get();
}

std::unique_ptr<Group> SceneParser::parseGroup(int depth) {
  t_.expect("{", "after 'Group'");
  t_.expect("numObjects", "at the start of Group");
  const int n = t_.integer("numObjects", 0, 1 << 30);
  auto group = std::make_unique<Group>();
  int count = 0;
  for (;;) {
    const Token& k = t_.peek();
    if (k.text == "}") {
      if (count < n)
        t_.fail(k.line, "Group: numObjects is " + std::to_string(n) + " but only " + std::to_string(count) +
                            " objects are given before '}'");
      t_.next("'}'");
      return group;
    }
    if (k.text == "MaterialIndex") {
      t_.next("MaterialIndex");
      const int line = t_.peek().line;
      const int m = t_.integer("MaterialIndex", -(1 << 30), 1 << 30);
      const int nm = static_cast<int>(scene_.materials.size());
      if (m < 0 || m >= nm)
        t_.fail(line, "MaterialIndex " + std::to_string(m) + " out of range: the scene declares " +
                          std::to_string(nm) + " materials" +
                          (nm ? " (0.." + std::to_string(nm - 1) + ")" : std::string()));
      current_ = m;
      continue;
    }
    if (!isObjectKind(k.text))
      t_.fail(k.line, "unknown keyword " + TokenStream::describe(k) + " in Group: expected " + kObjectList +
                          ", MaterialIndex or '}'");
    if (count == n)
      t_.fail(k.line, "Group: more objects than numObjects " + std::to_string(n) + ": found an extra '" + k.text + "'");
    group->children.push_back(parseObject(depth + 1));
    ++count;
  }
}

std::unique_ptr<Object> SceneParser::parseObject(int depth) {
  const Token& k = t_.next(std::string("an object (") + kObjectList + ")");
  if (!isObjectKind(k.text))
    t_.fail(k.line, "unknown keyword " + TokenStream::describe(k) + ": expected an object (" + kObjectList + ")");
  if (depth > kMaxNesting)
    t_.fail(k.line, "objects nested deeper than " + std::to_string(kMaxNesting) + " Group/Transform levels");
  if (k.text == "Group") return parseGroup(depth);
  if (k.text == "Transform") return parseTransform(k, depth);
  if (k.text == "TriangleMesh") return parseMesh(k);

  t_.expect("{", "after '" + k.text + "'");
  if (k.text == "Sphere") {
    FieldBlock f(t_, k.text, {{"center", FieldKind::Vec3}, {"radius"}});
    f.require({"center", "radius"});
    if (!(f.number("radius") > 0.f)) f.fail("radius", "must be positive, found " + std::to_string(f.number("radius")));
    return std::make_unique<Sphere>(f.vec3("center"), f.number("radius"), currentMaterial(k));
  }
  if (k.text == "Plane") {
    FieldBlock f(t_, k.text, {{"normal", FieldKind::Vec3}, {"offset"}});
    f.require({"normal", "offset"});
    if (f.vec3("normal").norm() == 0.f) f.fail("normal", "must not be the zero vector");
    return std::make_unique<Plane>(f.vec3("normal"), f.number("offset"), currentMaterial(k));
  }
  FieldBlock f(t_, k.text, {{"vertex0", FieldKind::Vec3}, {"vertex1", FieldKind::Vec3}, {"vertex2", FieldKind::Vec3}});
  f.require({"vertex0", "vertex1", "vertex2"});
  return std::make_unique<Triangle>(f.vec3("vertex0"), f.vec3("vertex1"), f.vec3("vertex2"), currentMaterial(k));
}

std::unique_ptr<Object> SceneParser::parseTransform(const Token& keyword, int depth) {
  t_.expect("{", "after 'Transform'");
  Mat4 m = Mat4::Identity();
  while (parseTransformOp(m)) {}
  if (t_.peek().text == "}")
    t_.fail(t_.peek().line, "Transform needs exactly one object before '}'");
  auto child = parseObject(depth + 1);
  const Token& close = t_.next("'}' closing Transform");
  if (close.text != "}")
    t_.fail(close.line, "expected '}' closing the Transform of line " + std::to_string(keyword.line) +
                            " (a Transform holds exactly one object, after its ops), found " +
                            TokenStream::describe(close));
  const float det = m.topLeftCorner<3, 3>().determinant();
  if (!std::isfinite(det) || std::abs(det) < 1e-12f)
    t_.fail(keyword.line, "Transform: the matrix is singular (determinant " + std::to_string(det) + ")");
  return std::make_unique<aliaslab::Transform>(m, std::move(child));
}

bool SceneParser::parseTransformOp(Mat4& m) {
  const std::string op = t_.peek().text;
  Mat4 a = Mat4::Identity();
  Eigen::Affine3f t = Eigen::Affine3f::Identity();
  if (op == "Scale") {
    t_.next(op);
    t.scale(t_.vec3("Scale"));
  } else if (op == "UniformScale") {
    t_.next(op);
    t.scale(t_.number("UniformScale"));
  } else if (op == "Translate") {
    t_.next(op);
    t.translate(t_.vec3("Translate"));
  } else if (op == "XRotate" || op == "YRotate" || op == "ZRotate") {
    t_.next(op);
    const Vec3 axis = op[0] == 'X' ? Vec3::UnitX() : op[0] == 'Y' ? Vec3::UnitY() : Vec3::UnitZ();
    t.rotate(Eigen::AngleAxisf(t_.number(op) * kPi / 180.f, axis));
  } else if (op == "Rotate") {
    t_.next(op);
    t_.expect("{", "after 'Rotate'");
    const int line = t_.peek().line;
    const Vec3 axis = t_.vec3("Rotate axis");
    if (axis.norm() == 0.f) t_.fail(line, "Rotate: the axis must not be the zero vector");
    t.rotate(Eigen::AngleAxisf(t_.number("Rotate angle") * kPi / 180.f, axis.normalized()));
    t_.expect("}", "closing Rotate { axis degrees }");
  } else if (op == "Matrix") {
    t_.next(op);
    t_.expect("{", "after 'Matrix'");
    const int line = t_.peek().line;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) a(r, c) = t_.number("Matrix");
    if (a.row(3) != Vec4(0.f, 0.f, 0.f, 1.f).transpose())
      t_.fail(line, "Matrix: the last row must be 0 0 0 1 (affine transforms only)");
    t_.expect("}", "after the 16 numbers of Matrix");
  } else {
    return false;
  }
  m = m * (op == "Matrix" ? a : t.matrix());
  return true;
}

std::unique_ptr<Object> SceneParser::parseMesh(const Token& keyword) {
  namespace fs = std::filesystem;
  t_.expect("{", "after 'TriangleMesh'");
  FieldBlock f(t_, "TriangleMesh", {{"obj_file", FieldKind::Word}});
  f.require({"obj_file"});
  const std::string name = f.word("obj_file");
  const Material* material = currentMaterial(keyword);

  // Resolve next to the scene file first, then in the working directory.
  std::vector<fs::path> candidates;
  if (fs::path(name).is_absolute() || baseDir_.empty()) candidates.push_back(name);
  else candidates = {fs::path(baseDir_) / name, fs::path(name)};
  std::string resolved;
  std::error_code ec;
  for (const fs::path& c : candidates)
    if (resolved.empty() && fs::is_regular_file(c, ec)) resolved = c.string();
  if (resolved.empty()) {
    std::string looked;
    for (const fs::path& c : candidates) looked += (looked.empty() ? "'" : " and '") + c.string() + "'";
    f.fail("obj_file", "names a missing OBJ file '" + name + "' (looked for " + looked + ")");
  }

  // Load; errors keep the OBJ file's own file:line inside ours.
  try {
    auto mesh = loadObj(resolved, material);
    scene_.dependencies.push_back(resolved);
    return mesh;
  } catch (const InputError& e) {
    f.fail("obj_file", "cannot load the mesh: " + std::string(e.what()));
  }
}

}  // namespace aliaslab::detail
