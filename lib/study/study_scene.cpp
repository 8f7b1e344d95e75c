#include "study/study_scene.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "core/files.h"
#include "core/hash.h"

namespace aliaslab {

std::string readFileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot open for reading");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

uint64_t hashBytes(const std::string& bytes, uint64_t seed) {
  uint64_t h = hashWords(seed, bytes.size());
  size_t i = 0;
  for (; i + 8 <= bytes.size(); i += 8) {
    uint64_t word;
    std::memcpy(&word, bytes.data() + i, 8);
    h = hashWords(h, word);
  }
  uint64_t tail = 0;
  std::memcpy(&tail, bytes.data() + i, bytes.size() - i);
  return hashWords(h, tail);
}

std::string describeTraceOptions(const TraceOptions& o) {
  std::ostringstream ss;
  if (o.shadows) ss << "-shadows ";
  ss << "-bounces " << o.bounces << " -weight " << o.weight;
  if (o.shadeBack) ss << " -shade_back";
  return ss.str();
}

RenderLine readRenderLine(const std::string& path) {
  requireRegularFile(path, "a scene is read from a regular file");
  std::string bytes = readFileBytes(path);
  // Line breaks as the scene parser reads them: "\n", "\r\n" or a lone "\r".
  for (size_t i = 0; i < bytes.size(); ++i)
    if (bytes[i] == '\r' && (i + 1 == bytes.size() || bytes[i + 1] != '\n')) bytes[i] = '\n';
  std::istringstream in(bytes);
  RenderLine r;
  std::string text;
  for (int lineNo = 1; std::getline(in, text); ++lineNo) {
    const size_t at = text.find("# render:");
    if (at == std::string::npos) continue;
    std::istringstream ss(text.substr(at + 9));
    std::vector<std::string> tok;
    for (std::string t; ss >> t;) tok.push_back(t);
    auto number = [&](size_t& k, const std::string& flag) {
      if (k + 1 >= tok.size()) throw ParseError(path, lineNo, "render line: " + flag + " needs a value");
      try {
        size_t used = 0;
        const double v = std::stod(tok[++k], &used);
        if (used != tok[k].size() || !std::isfinite(v)) throw std::invalid_argument("x");
        return v;
      } catch (const std::exception&) {
        throw ParseError(path, lineNo, "render line: expected a number after " + flag + ", found '" + tok[k] + "'");
      }
    };
    for (size_t k = 0; k < tok.size(); ++k) {
      const std::string& f = tok[k];
      if (f == "-size") {
        r.width = static_cast<int>(number(k, f));
        r.height = static_cast<int>(number(k, f));
        if (r.width < 1 || r.height < 1) throw ParseError(path, lineNo, "render line: -size must be positive");
      } else if (f == "-shadows") {
        r.options.shadows = true;
      } else if (f == "-shade_back") {
        r.options.shadeBack = true;
      } else if (f == "-bounces") {
        r.options.bounces = static_cast<int>(number(k, f));
        if (r.options.bounces < 0 || r.options.bounces > kMaxBounces)
          throw ParseError(path, lineNo, "render line: -bounces must be in 0.." + std::to_string(kMaxBounces));
      } else if (f == "-weight") {
        r.options.weight = static_cast<float>(number(k, f));
      } else if (f == "-grid") {
        for (int& g : r.grid) g = static_cast<int>(number(k, f));
        if (r.grid[0] < 0 || r.grid[1] < 0 || r.grid[2] < 0)
          throw ParseError(path, lineNo, "render line: -grid resolutions must be >= 0 (0 = automatic)");
      } else {
        throw ParseError(path, lineNo, "render line: unknown flag '" + f +
                                           "' (expected -size, -shadows, -bounces, -weight, -shade_back, -grid)");
      }
    }
    if (r.width == 0) throw ParseError(path, lineNo, "render line: missing -size W H");
    r.found = true;
    return r;
  }
  return r;
}

SceneSize studySceneSize(const std::string& path, const RenderLine& line, int width, int height, int maxSize,
                         int longSide) {
  // Size: override, else the render line, then the optional cap.
  SceneSize s;
  if (width > 0 && height > 0) s.width = width, s.height = height;
  else if (line.found) s.width = line.width, s.height = line.height;
  else throw FileError(path, "no '# render: -size W H' line and no {size} given");
  if (longSide > 0) maxSize = longSide;
  if (maxSize > 0 && (std::max(s.width, s.height) > maxSize || longSide > 0)) {
    const double scale = static_cast<double>(maxSize) / std::max(s.width, s.height);
    s.width = std::max(1, static_cast<int>(std::lround(s.width * scale)));
    s.height = std::max(1, static_cast<int>(std::lround(s.height * scale)));
  }
  return s;
}

SceneSize checkStudyScene(const std::string& path, int width, int height, int maxSize, int longSide) {
  const SceneSize size = studySceneSize(path, readRenderLine(path), width, height, maxSize, longSide);
  parseScene(path);  // the scene and its meshes parse (no acceleration structure)
  return size;
}

std::unique_ptr<StudyScene> loadStudyScene(const std::string& path, int width, int height, int maxSize,
                                           int longSide) {
  auto s = std::make_unique<StudyScene>();
  s->path = path;
  s->stem = std::filesystem::path(path).stem().string();
  s->line = readRenderLine(path);
  const SceneSize size = studySceneSize(path, s->line, width, height, maxSize, longSide);
  s->width = size.width, s->height = size.height;

  s->scene = parseScene(path);
  const int* g = s->line.grid;
  s->aggregate = makeDefaultAggregate(*s->scene.root, g[0], g[1], g[2]);  // mesh scenes: the BVH
  s->tracer = std::make_unique<Tracer>(s->scene, *s->aggregate, s->line.options);

  // Content hash: scene bytes, OBJ bytes, size, tracing flags.
  uint64_t h = hashBytes(readFileBytes(path), 0x5ce4e);
  for (const std::string& dep : s->scene.dependencies) h = hashBytes(readFileBytes(dep), h);
  h = hashBytes(describeTraceOptions(s->line.options), hashWords(h, s->width, s->height));
  s->contentHash = h;
  return s;
}

}  // namespace aliaslab
