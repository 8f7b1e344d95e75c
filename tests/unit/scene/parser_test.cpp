// Scene parser: each block builds the objects the format defines (checked
// through cameras' rays, lights' illumination, materials' responses and
// the geometry's bounds and hits), and each malformed input gives a
// ParseError naming the file, the right line and what was expected.
#include "aliaslab_paths.h"
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "scene/scene.h"

using namespace aliaslab;

namespace {

const std::string kData = std::string(ALIASLAB_TEST_DATA) + "/parser/";
// Line 1: camera looking down -z; line 2: two materials (red, green).
const std::string kHead =
    "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 4 }\n"
    "Materials { numMaterials 2 PhongMaterial { diffuseColor 1 0 0 } Material { diffuseColor 0 1 0 } }\n";

Scene parse(const std::string& text) { return parseSceneText(text, "scene.txt", ""); }
Scene parseWithHead(const std::string& group) { return parse(kHead + group); }

/// First hit of the ray origin + t dir over the whole scene.
Hit shoot(const Scene& s, const Vec3& origin, const Vec3& dir) {
  Hit hit;
  s.root->intersect(Ray{origin, dir}, 0.f, hit);
  return hit;
}

void expectNear(const Vec3& a, const Vec3& b, float tol = 1e-5f) {
  EXPECT_NEAR(a.x(), b.x(), tol);
  EXPECT_NEAR(a.y(), b.y(), tol);
  EXPECT_NEAR(a.z(), b.z(), tol);
}

}  // namespace

// ---------------------------------------------------------------- blocks

TEST(ParserCamera, OrthographicScreenMapsToSquareOfSideSize) {
  Scene s = parseWithHead("Group { numObjects 0 }\n");
  const Ray centre = s.camera->generateRay(Vec2(0.5f, 0.5f));
  expectNear(centre.origin, Vec3(0, 0, 10));
  expectNear(centre.direction.normalized(), Vec3(0, 0, -1));
  // horizontal = D x U = (1, 0, 0); screen x = 1 is half the size (2) to the right.
  expectNear(s.camera->generateRay(Vec2(1.f, 0.5f)).origin, Vec3(2, 0, 10));
  expectNear(s.camera->generateRay(Vec2(0.5f, 0.f)).origin, Vec3(0, -2, 10));
}

TEST(ParserCamera, PerspectiveEdgeRayIsHalfTheFieldOfView) {
  Scene s = parse("PerspectiveCamera { center 1 2 3 direction 0 0 -2 up 0 1 0 angle 90 }\n");
  const Ray edge = s.camera->generateRay(Vec2(1.f, 0.5f));
  expectNear(edge.origin, Vec3(1, 2, 3));
  expectNear(edge.direction.normalized(), Vec3(1, 0, -1).normalized());  // tan(45 deg) = 1
  EXPECT_FLOAT_EQ(s.camera->tMin(), 0.f);
}

TEST(ParserBackground, ColorAndAmbientWithDefaults) {
  Scene s = parse(kHead + "Background { ambientLight 0.1 0.2 0.3 color 0.4 0.5 0.6 }\n");
  expectNear(s.background.matrix(), Vec3(0.4f, 0.5f, 0.6f));
  expectNear(s.ambient.matrix(), Vec3(0.1f, 0.2f, 0.3f));
  Scene d = parse(kHead);
  expectNear(d.background.matrix(), Vec3::Constant(0.5f));
  expectNear(d.ambient.matrix(), Vec3::Zero());
  ASSERT_TRUE(d.root);  // no Group: an empty root
  EXPECT_TRUE(d.root->children.empty());
}

TEST(ParserLights, DirectionalAndAttenuatedPoint) {
  Scene s = parse(kHead +
                  "Lights { numLights 3\n"
                  "  DirectionalLight { direction 0 -2 0 color 0.5 0.5 0.5 }\n"
                  "  PointLight { position 0 0 0 color 9 9 9 attenuation 1 2 3 }\n"
                  "  PointLight { color 1 2 3 position 0 4 0 }\n"
                  "}\n");
  ASSERT_EQ(s.lights.size(), 3u);
  Vec3 l;
  Color c;
  float d;
  s.lights[0]->illuminate(Vec3(5, 5, 5), l, c, d);
  expectNear(l, Vec3(0, 1, 0));  // towards the light: against its travel direction
  expectNear(c.matrix(), Vec3::Constant(0.5f));
  EXPECT_TRUE(std::isinf(d));
  s.lights[1]->illuminate(Vec3(2, 0, 0), l, c, d);  // d = 2: 9 / (1 + 2*2 + 3*4) = 9/17
  expectNear(l, Vec3(-1, 0, 0));
  EXPECT_NEAR(d, 2.f, 1e-6f);
  expectNear(c.matrix(), Vec3::Constant(9.f / 17.f));
  s.lights[2]->illuminate(Vec3(0, 0, 0), l, c, d);  // default attenuation 1 0 0
  expectNear(c.matrix(), Vec3(1, 2, 3));
}

TEST(ParserMaterials, PhongFieldsInAnyOrderWithDefaults) {
  Scene s = parse(
      "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 4 }\n"
      "Materials { numMaterials 2\n"
      "  PhongMaterial { exponent 3 specularColor 0.5 0.25 0 diffuseColor 0.1 0.2 0.3\n"
      "                  indexOfRefraction 1.5 transparentColor 0.4 0 0 reflectiveColor 0 0.6 0 }\n"
      "  Material { }\n"
      "}\n");
  ASSERT_EQ(s.materials.size(), 2u);
  const Material& m = *s.materials[0];
  const Vec3 p(0, 0, 0), n(0, 0, 1);
  expectNear(m.diffuse(p).matrix(), Vec3(0.1f, 0.2f, 0.3f));
  expectNear(m.reflective(p).matrix(), Vec3(0, 0.6f, 0));
  expectNear(m.transparent(p).matrix(), Vec3(0.4f, 0, 0));
  EXPECT_FLOAT_EQ(m.indexOfRefraction(p), 1.5f);
  // Light at 60 deg from n, viewer on n: n.l = 1/2, h at 30 deg, n.h = cos 30.
  const Vec3 l(std::sin(kPi / 3), 0, std::cos(kPi / 3));
  const float nh = std::cos(kPi / 6), spec = nh * nh * nh;
  const Color got = m.shade(p, n, n, l, Color::Ones());
  expectNear(got.matrix(), Vec3(0.1f * 0.5f + 0.5f * spec, 0.2f * 0.5f + 0.25f * spec, 0.3f * 0.5f), 1e-5f);
  const Material& d = *s.materials[1];  // all defaults
  expectNear(d.diffuse(p).matrix(), Vec3::Ones());
  expectNear(d.reflective(p).matrix(), Vec3::Zero());
  EXPECT_FLOAT_EQ(d.indexOfRefraction(p), 1.f);
}

TEST(ParserMaterials, CheckerboardTransformMapsWorldIntoTextureSpace) {
  // q = 2 p: p.x = 0.6 lands in cell floor(1.2) = 1 (odd: second material).
  Scene s = parse(kHead.substr(0, kHead.find('\n') + 1) +
                  "Materials { numMaterials 3 Material { diffuseColor 1 0 0 } Material { diffuseColor 0 1 0 }\n"
                  "  Checkerboard { Transform { UniformScale 2 } materialIndex 0 materialIndex 1 } }\n");
  const Material& c = *s.materials[2];
  expectNear(c.diffuse(Vec3(0.25f, 0.25f, 0.25f)).matrix(), Vec3(1, 0, 0));
  expectNear(c.diffuse(Vec3(0.6f, 0.1f, 0.1f)).matrix(), Vec3(0, 1, 0));
  expectNear(c.diffuse(Vec3(0.6f, 0.6f, 0.1f)).matrix(), Vec3(1, 0, 0));  // cells 1 + 1 + 0 even
}

TEST(ParserMaterials, ProceduralsAndPatternExtension) {
  Scene s = parse(kHead.substr(0, kHead.find('\n') + 1) +
                  "Materials { numMaterials 7 Material { diffuseColor 1 0 0 } Material { diffuseColor 0 1 0 }\n"
                  "  Noise { materialIndex 0 materialIndex 1 octaves 3 }\n"
                  "  Marble { Transform { Scale 1 1 1 } materialIndex 0 materialIndex 2 octaves 2 frequency 3 "
                  "amplitude 0 }\n"
                  "  Wood { materialIndex 3 materialIndex 1 octaves 1 frequency 2 amplitude 0.5 }\n"
                  "  Pattern { Transform { Translate 0.5 0 0 } materialIndex 0 materialIndex 1 type stripes "
                  "frequency 1 }\n"
                  "  Pattern { materialIndex 0 materialIndex 1 frequency 1 type zoneplate } }\n");
  ASSERT_EQ(s.materials.size(), 7u);
  // Marble with amplitude 0: w = (sin(3 x) + 1) / 2 goes to the FIRST material (SCENE_FORMAT's formula);
  // at x = pi/6, w = 1: material 0 alone; at x = -pi/6, w = 0: material 2 (Noise of 0 and 1) alone.
  const Vec3 p(kPi / 6, 0.3f, 0.7f);
  expectNear(s.materials[3]->diffuse(p).matrix(), s.materials[0]->diffuse(p).matrix());
  const Vec3 p2(-kPi / 6, 0.3f, 0.7f);
  expectNear(s.materials[3]->diffuse(p2).matrix(), s.materials[2]->diffuse(p2).matrix());
  // Stripes on q = p + (0.5, 0, 0): w = 1 where sin(2 pi q.x) >= 0.
  expectNear(s.materials[5]->diffuse(Vec3(-0.25f, 0, 0)).matrix(), Vec3(0, 1, 0));  // q.x = 0.25
  expectNear(s.materials[5]->diffuse(Vec3(0.25f, 0, 0)).matrix(), Vec3(1, 0, 0));   // q.x = 0.75
  // Zone plate: w = 0.5 + 0.5 sin(x^2 + y^2) = 0.5 at the origin.
  expectNear(s.materials[6]->diffuse(Vec3::Zero()).matrix(), Vec3(0.5f, 0.5f, 0));
}

TEST(ParserGroup, PrimitivesNestedGroupsAndMaterialIndex) {
  Scene s = parseWithHead(
      "Group { numObjects 3\n"
      "  Sphere { center 0 0 0 radius 1 }\n"           // before any MaterialIndex: material 0
      "  MaterialIndex 1\n"
      "  Group { numObjects 1 Triangle { vertex0 2 0 0 vertex1 3 0 0 vertex2 2 1 0 } }\n"
      "  Plane { normal 0 0 2 offset -5 }\n"
      "}\n");
  ASSERT_EQ(s.root->children.size(), 3u);
  Hit h = shoot(s, Vec3(0, 0, 10), Vec3(0, 0, -1));
  EXPECT_NEAR(h.t, 9.f, 1e-5f);
  EXPECT_EQ(h.material, s.materials[0].get());
  h = shoot(s, Vec3(2.2f, 0.2f, 10), Vec3(0, 0, -1));  // the triangle inherits MaterialIndex 1
  EXPECT_NEAR(h.t, 10.f, 1e-5f);
  EXPECT_EQ(h.material, s.materials[1].get());
  h = shoot(s, Vec3(-3, 0, 10), Vec3(0, 0, -1));  // n.P = d: 2 z = -5, the plane z = -2.5
  EXPECT_NEAR(h.t, 12.5f, 1e-5f);
  EXPECT_EQ(h.material, s.materials[1].get());
}

TEST(ParserGroup, MaterialIndexStaysSetAfterNestedGroupCloses) {
  Scene s = parseWithHead(
      "Group { numObjects 2\n"
      "  Group { numObjects 0 MaterialIndex 1 }\n"
      "  Sphere { center 0 0 0 radius 1 }\n"
      "}\n");
  EXPECT_EQ(shoot(s, Vec3(0, 0, 10), Vec3(0, 0, -1)).material, s.materials[1].get());
}

TEST(ParserTransform, OpsComposeAsProductFirstAppliedLast) {
  // M = T(5,0,0) * S(2): centre (1,0,0) -> (2,0,0) -> (7,0,0), radius 2.
  Scene s = parseWithHead(
      "Group { numObjects 1 Transform { Translate 5 0 0 Scale 2 2 2 Sphere { center 1 0 0 radius 1 } } }\n");
  const BBox b = s.root->bounds();
  EXPECT_NEAR(b.min.x(), 5.f, 1e-4f);
  EXPECT_NEAR(b.max.x(), 9.f, 1e-4f);
  const Hit h = shoot(s, Vec3(7, 0, 10), Vec3(0, 0, -1));
  EXPECT_NEAR(h.t, 8.f, 1e-4f);
  expectNear(h.normal, Vec3(0, 0, 1), 1e-4f);
}

TEST(ParserTransform, RotationsMatrixAndUniformScale) {
  // XRotate 90 takes (0,1,0) to (0,0,1); Rotate {0 0 1 90} takes (1,0,0) to (0,1,0);
  // Matrix rows translate x by 3; UniformScale 3 scales radius 0.5 to 1.5.
  Scene s = parseWithHead(
      "Group { numObjects 4\n"
      "  Transform { XRotate 90 Sphere { center 0 1 0 radius 0.5 } }\n"
      "  Transform { Rotate { 0 0 1 90 } Sphere { center 10 0 0 radius 0.5 } }\n"
      "  Transform { Matrix { 1 0 0 3  0 1 0 0  0 0 1 0  0 0 0 1 } Sphere { center 0 -20 0 radius 0.5 } }\n"
      "  Transform { UniformScale 3 Transform { ZRotate 180 Sphere { center -10 -10 0 radius 0.5 } } }\n"
      "}\n");
  const auto& c = s.root->children;
  auto centre = [](const Object& o) { BBox b = o.bounds(); return Vec3(0.5f * (b.min + b.max)); };
  expectNear(centre(*c[0]), Vec3(0, 0, 1), 1e-4f);
  expectNear(centre(*c[1]), Vec3(0, 10, 0), 1e-4f);
  expectNear(centre(*c[2]), Vec3(3, -20, 0), 1e-4f);
  expectNear(centre(*c[3]), Vec3(30, 30, 0), 1e-3f);
  EXPECT_NEAR(c[3]->bounds().extent().z(), 3.f, 1e-3f);
}

TEST(ParserFile, MeshResolvedBesideSceneAndRecorded) {
  Scene s = parseScene(kData + "mesh_scene.txt");
  ASSERT_EQ(s.dependencies.size(), 1u);
  EXPECT_EQ(s.dependencies[0], kData + "tri.obj");
  const Hit h = shoot(s, Vec3(0.7f, 0.2f, 5), Vec3(0, 0, -1));
  EXPECT_NEAR(h.t, 5.f, 1e-5f);
  EXPECT_EQ(h.material, s.materials[0].get());
  EXPECT_FALSE(shoot(s, Vec3(1.5f, 0.5f, 5), Vec3(0, 0, -1)).found());
}

TEST(ParserFile, CommentsAndBlocksInAnyOrder) {
  Scene s = parse(
      "# a comment line\n"
      "Group { numObjects 1 MaterialIndex 1 # trailing comment\n"
      "  Sphere { center 0 0 0 radius 1 } }\n"
      "Materials { numMaterials 2 Material { } Material { diffuseColor 0 0 1 } }\n"
      "PerspectiveCamera{center 0 0 5 direction 0 0 -1 up 0 1 0 angle 30}\n");
  EXPECT_EQ(shoot(s, Vec3(0, 0, 5), Vec3(0, 0, -1)).material, s.materials[1].get());
}

TEST(ParserFile, MissingSceneFileIsFileError) {
  EXPECT_THROW(parseScene(kData + "no_such_scene.txt"), FileError);
}

// ---------------------------------------------------------------- errors

namespace {

struct BadScene {
  const char* name;      ///< what is wrong
  std::string text;      ///< the whole file
  int line;              ///< where the error must be reported
  const char* expected;  ///< a phrase the message must contain
};

const std::string kCam = kHead.substr(0, kHead.find('\n') + 1);  // line 1 only
std::string group(const std::string& body) { return kHead + "Group {\n" + body + "}\n"; }  // body from line 4

const BadScene kBad[] = {
    {"unknown top-level keyword", kHead + "\nCylinder { }\n", 4, "unknown keyword 'Cylinder'"},
    {"unknown object keyword", group("numObjects 1\nCone { }\n"), 5, "unknown keyword 'Cone' in Group"},
    {"unknown field", group("numObjects 1\nSphere { center 0 0 0 radiuss 1 }\n"), 5, "unknown field 'radiuss'"},
    {"missing field", group("numObjects 1\nSphere { center 0 0 0\n}\n"), 6, "missing field 'radius'"},
    {"extra token", group("numObjects 1\nSphere { center 0 0 0 radius 1 2 }\n"), 5, "unknown field '2'"},
    {"bad number", group("numObjects 1\nSphere {\ncenter 0 0 0\nradius abc }\n"), 7,
     "expected a number for 'radius', found 'abc'"},
    {"NaN", group("numObjects 1\nSphere { center 0 nan 0 radius 1 }\n"), 5, "finite number for 'center'"},
    {"infinity", group("numObjects 1\nSphere { center 0 0 0 radius inf }\n"), 5, "finite number for 'radius'"},
    {"zero radius", group("numObjects 1\nSphere { center 0 0 0 radius 0 }\n"), 5, "'radius' must be positive"},
    {"negative radius", group("numObjects 1\nSphere { center 0 0 0\n radius -2 }\n"), 6, "must be positive"},
    {"camera size zero", "OrthographicCamera { center 0 0 0 direction 0 0 -1 up 0 1 0\nsize 0 }\n", 2,
     "'size' must be positive"},
    {"camera angle 180", "\nPerspectiveCamera { center 0 0 0 direction 0 0 -1 up 0 1 0 angle 180 }\n", 2,
     "(0, 180)"},
    {"camera angle 0", "PerspectiveCamera { center 0 0 0 direction 0 0 -1 up 0 1 0 angle 0 }\n", 1, "(0, 180)"},
    {"up parallel to direction", "OrthographicCamera { center 0 0 0 direction 0 0 -1 up 0 0 2 size 1 }\n", 1,
     "parallel"},
    {"negative numObjects", group("numObjects -1\n"), 4, "'numObjects' must be in [0"},
    {"fractional numObjects", group("numObjects 1.5\n"), 4, "expected a whole number for 'numObjects'"},
    {"negative numLights", kHead + "Lights {\nnumLights -2 }\n", 4, "'numLights' must be in [0"},
    {"negative numMaterials", kCam + "Materials { numMaterials -1 }\n", 2, "'numMaterials' must be in [0"},
    {"MaterialIndex out of range", group("numObjects 0\nMaterialIndex 2\n"), 5, "MaterialIndex 2 out of range"},
    {"procedural refers to itself",
     kCam + "Materials { numMaterials 2 Material { }\nCheckerboard { materialIndex 0 materialIndex 1 } }\n", 3,
     "earlier material (0..0)"},
    {"procedural refers to later", kCam + "Materials { numMaterials 2\nNoise { materialIndex 1 materialIndex 0 octaves 2 }"
                                   " Material { } }\n",
     3, "earlier material"},
    {"fewer objects", group("numObjects 2\nSphere { center 0 0 0 radius 1 }\n"), 6, "only 1 objects"},
    {"more objects", group("numObjects 1\nSphere { center 0 0 0 radius 1 }\nSphere { center 0 0 0 radius 1 }\n"), 6,
     "more objects than numObjects 1"},
    {"fewer lights", kHead + "Lights { numLights 1\n}\n", 4, "only 0 lights"},
    {"more lights", kHead + "Lights { numLights 0\nPointLight { position 0 0 0 color 1 1 1 } }\n", 4,
     "more lights than numLights 0"},
    {"fewer materials", kCam + "Materials { numMaterials 3 Material { }\n}\n", 3, "only 1 materials"},
    {"more materials", kCam + "Materials { numMaterials 1 Material { }\nMaterial { } }\n", 3,
     "more materials than numMaterials 1"},
    {"unexpected end of file", kHead + "Group { numObjects 1\nSphere { center 0 0\n", 4, "unexpected end of file"},
    {"end of file inside a field", "OrthographicCamera { center 0 0 0 direction 0 0 -1 up 0 1 0 size", 1,
     "unexpected end of file"},
    {"missing camera", "Materials { numMaterials 0 }\n\n", 1, "missing camera"},
    {"second camera", kHead + "PerspectiveCamera { center 0 0 0 direction 0 0 -1 up 0 1 0 angle 30 }\n", 3,
     "second camera"},
    {"duplicate field", group("numObjects 1\nSphere { radius 1 center 0 0 0\nradius 2 }\n"), 6, "given twice"},
    {"singular transform", group("numObjects 1\nTransform { Scale 1 0 1\nSphere { center 0 0 0 radius 1 } }\n"), 5,
     "singular"},
    {"two objects in a transform",
     group("numObjects 1\nTransform { Sphere { center 0 0 0 radius 1 }\nSphere { center 0 0 0 radius 1 } }\n"), 6,
     "exactly one object"},
    {"no material", "OrthographicCamera { center 0 0 0 direction 0 0 -1 up 0 1 0 size 1 }\n"
                    "Group { numObjects 1\nSphere { center 0 0 0 radius 1 } }\n",
     3, "no Materials"},
    {"bad pattern type", kCam + "Materials { numMaterials 3 Material { } Material { }\n"
                         "Pattern { materialIndex 0 materialIndex 1\ntype moire frequency 2 } }\n",
     4, "zoneplate, sinc, siemens, stripes or grating"},
    {"angle of a non-grating", kCam + "Materials { numMaterials 3 Material { } Material { }\n"
                               "Pattern { materialIndex 0 materialIndex 1\ntype sinc frequency 2\nangle 30 } }\n",
     5, "'angle' is a key of the grating only"},
};

class ParserErrors : public testing::TestWithParam<BadScene> {};

}  // namespace

TEST_P(ParserErrors, NamesFileLineAndExpectation) {
  const BadScene& b = GetParam();
  try {
    parse(b.text);
    FAIL() << b.name << ": no ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "scene.txt") << b.name;
    EXPECT_EQ(e.line(), b.line) << b.name << ": " << e.what();
    EXPECT_NE(std::string(e.what()).find("scene.txt:" + std::to_string(b.line) + ": "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(b.expected), std::string::npos) << b.name << ": " << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, ParserErrors, testing::ValuesIn(kBad), [](const auto& info) {
  std::string n = info.param.name;
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
});

TEST(ParserErrorsNesting, DeepNestingIsAnErrorNotAStackOverflow) {
  std::string text = kHead + "Group { numObjects 1\n";  // line 3
  for (int i = 0; i < 100000; ++i) text += "Group { numObjects 1 ";
  for (int i = 0; i < 100001; ++i) text += "} ";
  try {
    parse(text);
    FAIL() << "no ParseError";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("nested deeper than 256"), std::string::npos) << e.what();
  }
  // 200 levels, properly closed, are fine.
  std::string ok = kHead;
  for (int i = 0; i < 200; ++i) ok += "Group { numObjects 1\n";
  ok += "Sphere { center 0 0 0 radius 1 }\n";
  for (int i = 0; i < 200; ++i) ok += "}\n";
  EXPECT_NEAR(shoot(parse(ok), Vec3(0, 0, 10), Vec3(0, 0, -1)).t, 9.f, 1e-5f);
}

TEST(ParserErrorsMesh, MalformedObjNamesBothFiles) {
  try {
    parseScene(kData + "bad_mesh_scene.txt");
    FAIL() << "no ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 5);  // the TriangleMesh line
    const std::string msg = e.what();
    EXPECT_NE(msg.find("bad_mesh_scene.txt:5:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("bad.obj:3:"), std::string::npos) << msg;  // the OBJ's own line
  }
}

TEST(ParserErrorsMesh, MissingObjNamesSceneLineAndPathsTried) {
  try {
    parseScene(kData + "missing_mesh_scene.txt");
    FAIL() << "no ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 6);
    EXPECT_NE(std::string(e.what()).find("no_such_mesh.obj"), std::string::npos) << e.what();
  }
}
