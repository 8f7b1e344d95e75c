// Scene file parser: top-level blocks, cameras, background and lights.
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.h"
#include "core/files.h"
#include "scene/parser_fields.h"
#include "scene/parser_impl.h"
#include "scene/scene.h"

namespace aliaslab {
namespace detail {

void SceneParser::parse() {
  // Locate the top-level blocks; each kind at most once.
  struct Block {
    size_t open;  ///< index of its '{'
    size_t end;   ///< index after its '}'
    int line;
    std::string kind;
  };
  static const char* kinds[] = {"OrthographicCamera", "PerspectiveCamera", "Background", "Lights", "Materials",
                                "Group"};
  std::map<std::string, Block> blocks;  // keyed by role: camera or the block's name
  while (!t_.atEnd()) {
    const Token& k = t_.next("a block");
    if (k.text == "}" && !blocks.empty()) {
      // A '}' after the last block closed: some '{' inside that block is missing.
      const Block* last = &blocks.begin()->second;
      for (const auto& [role, b] : blocks) last = b.end > last->end ? &b : last;
      t_.fail(k.line, "unmatched '}': the " + last->kind + " block opened at line " + std::to_string(last->line) +
                          " already closed; is a '{' missing inside it?");
    }
    bool known = false;
    for (const char* name : kinds) known = known || k.text == name;
    if (!known)
      t_.fail(k.line, "unknown keyword " + TokenStream::describe(k) +
                          ": expected OrthographicCamera, PerspectiveCamera, Background, Lights, Materials or Group");
    const std::string role = k.text.find("Camera") != std::string::npos ? "camera" : k.text;
    if (auto it = blocks.find(role); it != blocks.end())
      t_.fail(k.line, "second " + role + " block '" + k.text + "' (the first is at line " +
                          std::to_string(it->second.line) + ")");
    const size_t open = t_.position();
    if (t_.peek().text != "{") t_.expect("{", "after '" + k.text + "'");
    const size_t end = t_.skipBlock(open, k.text);
    blocks[role] = Block{open, end, k.line, k.text};
    t_.seek(end);
  }
  if (!blocks.count("camera"))
    t_.fail(t_.lastLine(), "missing camera: expected an OrthographicCamera or PerspectiveCamera block");

  // Parse in dependency order.
  for (const char* role : {"camera", "Background", "Lights", "Materials", "Group"}) {
    auto it = blocks.find(role);
    if (it == blocks.end()) continue;
    const Block& b = it->second;
    t_.seek(b.open);
    try {
      if (b.kind == "Background") parseBackground();
      else if (b.kind == "Lights") parseLights();
      else if (b.kind == "Materials") parseMaterials();
      else if (b.kind == "Group") scene_.root = parseGroup(0);
      else parseCamera(b.kind);
    } catch (const ParseError&) {
      throw;
    } catch (const InputError& e) {  // a factory's own check: place it in this block
      t_.fail(b.line, b.kind + ": " + e.what());
    }
    if (t_.position() != b.end) t_.fail(t_.peek().line, "unexpected " + TokenStream::describe(t_.peek()));
  }
  if (!scene_.root) scene_.root = std::make_unique<Group>();
}

void SceneParser::parseCamera(const std::string& kind) {
  const bool ortho = kind == "OrthographicCamera";
  const std::string extent = ortho ? "size" : "angle";
  t_.expect("{", "after '" + kind + "'");
  FieldBlock f(t_, kind,
               {{"center", FieldKind::Vec3}, {"direction", FieldKind::Vec3}, {"up", FieldKind::Vec3}, {extent}});
  f.require({"center", "direction", "up", extent});
  const Vec3 d = f.vec3("direction"), up = f.vec3("up");
  if (d.norm() == 0.f) f.fail("direction", "must not be the zero vector");
  if (d.normalized().cross(up).norm() < 1e-6f * up.norm() || up.norm() == 0.f)
    f.fail("up", "must not be zero or parallel to 'direction'");
  const float s = f.number(extent);
  if (ortho) {
    if (!(s > 0.f)) f.fail("size", "must be positive, found " + std::to_string(s));
    scene_.camera = makeOrthographicCamera(f.vec3("center"), d, up, s);
  } else {
    if (!(s > 0.f && s < 180.f)) f.fail("angle", "must be in (0, 180) degrees, found " + std::to_string(s));
    scene_.camera = makePerspectiveCamera(f.vec3("center"), d, up, s);
  }
}

void SceneParser::parseBackground() {
  t_.expect("{", "after 'Background'");
  FieldBlock f(t_, "Background", {{"color", FieldKind::Vec3}, {"ambientLight", FieldKind::Vec3}});
  scene_.background = f.vec3("color", Vec3::Constant(0.5f)).array();
  scene_.ambient = f.vec3("ambientLight", Vec3::Zero()).array();
}

void SceneParser::parseLights() {
  t_.expect("{", "after 'Lights'");
  t_.expect("numLights", "at the start of Lights");
  const int n = t_.integer("numLights", 0, 1 << 30);
  int count = 0;
  for (;;) {
    const Token& k = t_.next("a light or '}'");
    if (k.text == "}") {
      if (count < n)
        t_.fail(k.line, "Lights: numLights is " + std::to_string(n) + " but only " + std::to_string(count) +
                            " lights are given before '}'");
      return;
    }
    if (k.text != "DirectionalLight" && k.text != "PointLight")
      t_.fail(k.line, "unknown keyword " + TokenStream::describe(k) +
                          " in Lights: expected DirectionalLight, PointLight or '}'");
    if (count == n)
      t_.fail(k.line, "Lights: more lights than numLights " + std::to_string(n) + ": found an extra '" + k.text + "'");
    ++count;
    t_.expect("{", "after '" + k.text + "'");
    if (k.text == "DirectionalLight") {
      FieldBlock f(t_, k.text, {{"direction", FieldKind::Vec3}, {"color", FieldKind::Vec3}});
      f.require({"direction", "color"});
      if (f.vec3("direction").norm() == 0.f) f.fail("direction", "must not be the zero vector");
      scene_.lights.push_back(makeDirectionalLight(f.vec3("direction"), f.vec3("color").array()));
    } else {
      FieldBlock f(t_, k.text,
                   {{"position", FieldKind::Vec3}, {"color", FieldKind::Vec3}, {"attenuation", FieldKind::Vec3}});
      f.require({"position", "color"});
      const Vec3 a = f.vec3("attenuation", Vec3(1.f, 0.f, 0.f));
      if ((a.array() < 0.f).any() || a.sum() <= 0.f)
        f.fail("attenuation", "needs c0, c1, c2 >= 0, not all zero");
      scene_.lights.push_back(makePointLight(f.vec3("position"), f.vec3("color").array(), a[0], a[1], a[2]));
    }
  }
}

}  // namespace detail

Scene parseSceneText(const std::string& text, const std::string& name, const std::string& baseDir) {
  Scene scene;
  scene.path = name;
  scene.render = parseRenderLine(text, name);
  detail::TokenStream tokens(text, name);
  detail::SceneParser(tokens, scene, baseDir).parse();
  return scene;
}

Scene parseScene(const std::string& path) {
  requireRegularFile(path, "a scene is read from a regular file");  // (a FIFO would block the reader)
  std::ifstream in(path, std::ios::binary);
  if (!in || std::filesystem::is_directory(path)) throw FileError(path, "cannot open the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw FileError(path, "cannot read the scene file");
  return parseSceneText(text.str(), path, std::filesystem::path(path).parent_path().string());
}

}  // namespace aliaslab
