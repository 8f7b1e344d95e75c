// The scene-file primitives and containers.
#pragma once
#include <string>

#include "geometry/object.h"

namespace aliaslab {

/// Sphere { center C radius R }
class Sphere final : public Object {
 public:
  Sphere(const Vec3& center, float radius, const Material* material);
  bool intersect(const Ray& ray, float tmin, Hit& hit) const override;
  BBox bounds() const override;
  void flatten(const Mat4& toWorld, ObjectList& out) const override;
  std::unique_ptr<Object> clone() const override;

  Vec3 center;
  float radius;
  const Material* material;
};

/// Plane { normal n offset d }: the infinite plane n.P = d, whatever |n| (kept as n / |n| and d / |n|).
class Plane final : public Object {
 public:
  Plane(const Vec3& normal, float offset, const Material* material);
  bool intersect(const Ray& ray, float tmin, Hit& hit) const override;
  BBox bounds() const override;  ///< infinite
  void flatten(const Mat4& toWorld, ObjectList& out) const override;
  std::unique_ptr<Object> clone() const override;

  Vec3 normal;
  float offset;
  const Material* material;
};

/// Triangle { vertex0 a vertex1 b vertex2 c }; counter-clockwise is the front face.
class Triangle final : public Object {
 public:
  Triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Material* material);
  bool intersect(const Ray& ray, float tmin, Hit& hit) const override;
  BBox bounds() const override;
  void flatten(const Mat4& toWorld, ObjectList& out) const override;  ///< bakes toWorld into the vertices
  std::unique_ptr<Object> clone() const override;

  Vec3 a, b, c;
  const Material* material;
};

/// A list of children (Group, and the triangles of a mesh).
class Group final : public Object {
 public:
  explicit Group(ObjectList children = {});
  bool intersect(const Ray& ray, float tmin, Hit& hit) const override;
  BBox bounds() const override;
  void flatten(const Mat4& toWorld, ObjectList& out) const override;
  std::unique_ptr<Object> clone() const override;

  ObjectList children;
};

/// Transform { ops <object> }: the child lives in object space; `matrix`
/// maps object space to the parent's space.
class Transform final : public Object {
 public:
  Transform(const Mat4& matrix, std::unique_ptr<Object> child);
  bool intersect(const Ray& ray, float tmin, Hit& hit) const override;
  BBox bounds() const override;
  void flatten(const Mat4& toWorld, ObjectList& out) const override;
  std::unique_ptr<Object> clone() const override;

  Mat4 matrix, inverse;
  Mat3 normalMatrix;  ///< inverse transpose of the linear part
  std::unique_ptr<Object> child;
};

/// TriangleMesh { obj_file name.obj }: reads `v x y z` and `f i j k` lines
/// (1-based; other line types are ignored). Returns a Group of Triangles.
/// Throws FileError when the file cannot be opened and ParseError naming the
/// OBJ file and line for malformed content (bad number, index out of range,
/// a face with fewer than three vertices, no faces at all).
std::unique_ptr<Group> loadObj(const std::string& path, const Material* material);

}  // namespace aliaslab
