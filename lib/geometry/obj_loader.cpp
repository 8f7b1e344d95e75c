// Wavefront OBJ reader for triangle meshes: `v` and `f` lines only.
//
//   v x y z [w]            a vertex (w, if present, is ignored)
//   f i j k ...            a polygon, fan-triangulated (i, i/t, i//n, i/t/n;
//                          1-based, negative = relative to the last vertex)
// vn, vt, g, o, s, usemtl, mtllib, other keywords and `#` comments are
// skipped. Malformed content throws ParseError(file, line, what).
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <string_view>

#include "core/error.h"
#include "core/files.h"
#include "geometry/primitives.h"

namespace aliaslab {
namespace {

/// from_chars does not take a leading '+'; OBJ writers sometimes emit one.
std::string_view dropPlus(std::string_view tok) {
  return tok.size() > 1 && tok[0] == '+' && tok[1] != '-' && tok[1] != '+' ? tok.substr(1) : tok;
}

struct FaceRef {
  long index;  ///< 0-based vertex index (may still be out of range)
  int line;
};

float parseCoordinate(std::string_view tok, const std::string& path, int line) {
  float value = 0.f;
  const std::string_view num = dropPlus(tok);
  const auto [end, ec] = std::from_chars(num.data(), num.data() + num.size(), value);
  if (ec == std::errc::result_out_of_range)
    throw ParseError(path, line, "coordinate '" + std::string(tok) + "' is out of float range");
  if (ec != std::errc() || end != num.data() + num.size())
    throw ParseError(path, line, "expected a number, got '" + std::string(tok) + "'");
  if (!std::isfinite(value))
    throw ParseError(path, line, "coordinate '" + std::string(tok) + "' is not finite");
  return value;
}

/// The vertex part of `i`, `i/t`, `i//n` or `i/t/n`, resolved to 0-based.
long parseFaceIndex(std::string_view tok, long vertexCount, const std::string& path, int line) {
  const std::string_view head = dropPlus(tok.substr(0, tok.find('/')));
  long value = 0;
  const auto [end, ec] = std::from_chars(head.data(), head.data() + head.size(), value);
  if (head.empty() || ec != std::errc() || end != head.data() + head.size())
    throw ParseError(path, line, "expected a vertex index, got '" + std::string(tok) + "'");
  if (value == 0) throw ParseError(path, line, "vertex index 0 (OBJ indices start at 1)");
  if (value < 0) {
    const long resolved = vertexCount + value;
    if (resolved < 0)
      throw ParseError(path, line, "relative vertex index " + std::to_string(value) + " before the first vertex");
    return resolved;
  }
  return value - 1;
}

std::vector<std::string_view> splitTokens(std::string_view s) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
    size_t j = i;
    while (j < s.size() && s[j] != ' ' && s[j] != '\t' && s[j] != '\r') ++j;
    if (j > i) out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

}  // namespace

std::unique_ptr<Group> loadObj(const std::string& path, const Material* material) {
  requireRegularFile(path, "an OBJ file is read from a regular file");  // (a FIFO would block the reader)
  std::ifstream in(path);
  if (!in) throw FileError(path, "cannot open OBJ file");

  std::vector<Vec3> vertices;
  std::vector<std::array<FaceRef, 3>> triangles;
  std::string text;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    std::string_view body(text);
    body = body.substr(0, body.find('#'));
    const auto tok = splitTokens(body);
    if (tok.empty()) continue;

    // Vertices
    if (tok[0] == "v") {
      if (tok.size() != 4 && tok.size() != 5)
        throw ParseError(path, line, "a vertex needs 3 coordinates (and an optional w), got " +
                                         std::to_string(tok.size() - 1));
      vertices.emplace_back(parseCoordinate(tok[1], path, line), parseCoordinate(tok[2], path, line),
                            parseCoordinate(tok[3], path, line));
      if (tok.size() == 5) parseCoordinate(tok[4], path, line);
      continue;
    }
    // Faces, fan-triangulated
    if (tok[0] == "f") {
      if (tok.size() < 4)
        throw ParseError(path, line, "a face needs at least 3 vertices, got " + std::to_string(tok.size() - 1));
      const long n = static_cast<long>(vertices.size());
      std::vector<FaceRef> refs;
      for (size_t k = 1; k < tok.size(); ++k) refs.push_back({parseFaceIndex(tok[k], n, path, line), line});
      for (size_t k = 1; k + 1 < refs.size(); ++k) triangles.push_back({refs[0], refs[k], refs[k + 1]});
      continue;
    }
    // Everything else (vn, vt, g, o, s, usemtl, mtllib, ...) is ignored.
  }
  if (in.bad()) throw FileError(path, "read error");
  if (triangles.empty()) throw ParseError(path, std::max(line, 1), "no faces in OBJ file");

  // Resolve indices (positive ones may refer to vertices declared later)
  ObjectList tris;
  tris.reserve(triangles.size());
  const long n = static_cast<long>(vertices.size());
  for (const auto& t : triangles) {
    for (const auto& r : t)
      if (r.index >= n)
        throw ParseError(path, r.line, "vertex index " + std::to_string(r.index + 1) + " out of range (" +
                                           std::to_string(n) + " vertices)");
    tris.push_back(std::make_unique<Triangle>(vertices[t[0].index], vertices[t[1].index],
                                              vertices[t[2].index], material));
  }
  return std::make_unique<Group>(std::move(tris));
}

}  // namespace aliaslab
