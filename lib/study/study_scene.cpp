#include "study/study_scene.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/error.h"
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

SceneSize studySceneSize(const std::string& path, const RenderSettings& line, int width, int height, int maxSize,
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
  const Scene scene = parseScene(path);  // the scene, its render line and its meshes parse (no acceleration structure)
  return studySceneSize(path, scene.render, width, height, maxSize, longSide);
}

std::unique_ptr<StudyScene> loadStudyScene(const std::string& path, int width, int height, int maxSize,
                                           int longSide) {
  auto s = std::make_unique<StudyScene>();
  s->path = path;
  s->stem = std::filesystem::path(path).stem().string();
  s->scene = parseScene(path);
  const SceneSize size = studySceneSize(path, s->scene.render, width, height, maxSize, longSide);
  s->width = size.width, s->height = size.height;
  s->options = traceOptionsOf(s->scene.render);
  const int* g = s->scene.render.grid;
  s->aggregate = makeDefaultAggregate(*s->scene.root, g[0], g[1], g[2]);  // mesh scenes: the BVH
  s->tracer = std::make_unique<Tracer>(s->scene, *s->aggregate, s->options);

  // Content hash: scene bytes, OBJ bytes, size, tracing flags.
  uint64_t h = hashBytes(readFileBytes(path), 0x5ce4e);
  for (const std::string& dep : s->scene.dependencies) h = hashBytes(readFileBytes(dep), h);
  h = hashBytes(describeTraceOptions(s->options), hashWords(h, s->width, s->height));
  s->contentHash = h;
  return s;
}

}  // namespace aliaslab
