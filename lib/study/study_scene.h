// A scene ready for the study: parsed, accelerated, with its tracer, the
// image size and tracing flags of its `# render:` line, and a content hash.
// Validation needs less: checkStudyScene() parses the scene and reads its size
// from the render line without building an acceleration structure or tracer;
// the sweep builds them once, in loadStudyScene(), when it reaches the scene.
//
// The scenes engineer puts exactly one machine-readable line in every scene:
//   # render: -size W H [-shadows] [-bounces n] [-weight w] [-shade_back] [-grid nx ny nz]
// The scene parser reads it as scene data (Scene::render, scene/render_settings.h).
// The content hash covers the scene file's bytes, every
// OBJ dependency's bytes, the size and the tracing flags: references cached
// under it are reused exactly when they would come out the same.
#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include "accel/aggregate.h"
#include "render/tracer.h"
#include "scene/scene.h"

namespace aliaslab {

/// The tracing flags as text ("-shadows -bounces 4 ..."), for manifests and hashes.
std::string describeTraceOptions(const TraceOptions& options);

/// 64-bit hash of a byte string, chained from `seed`.
uint64_t hashBytes(const std::string& bytes, uint64_t seed = 0);

/// Whole file as bytes. Throws FileError.
std::string readFileBytes(const std::string& path);

class StudyScene {
 public:
  std::string path;       ///< the scene file as given
  std::string stem;       ///< file name without folder and extension (the CSV's scene column)
  int width = 0, height = 0;
  Scene scene;            ///< with its render line, scene.render
  TraceOptions options;   ///< the render line's tracing flags (traceOptionsOf)
  std::unique_ptr<Aggregate> aggregate;
  std::unique_ptr<Tracer> tracer;
  uint64_t contentHash = 0;  ///< scene + OBJ bytes, size, tracing flags (+ the film offset when not zero)
  /// The camera's film offset in pixels while a study shifts it (study/sweep/alignment.h FilmOffsetCamera; the reference
  /// manifests record it); 0 0: the camera as the scene file has it.
  double filmOffset[2] = {0, 0};
};

struct SceneSize {
  int width = 0, height = 0;
};

/// The size a study renders the scene at: (width, height) when both > 0, else
/// the render line's size; then scaled down (aspect kept, rounded, >= 1) so the
/// larger side is at most maxSize when maxSize > 0; or, when longSide > 0,
/// scaled up or down (aspect kept, rounded, >= 1) so the larger side is
/// exactly longSide (maxSize is then ignored). Throws FileError naming `path`
/// when no size is known.
SceneSize studySceneSize(const std::string& path, const RenderSettings& line, int width = 0, int height = 0,
                         int maxSize = 0, int longSide = 0);

/// Checks a scene as loadStudyScene would, without building it: its render line, its size (studySceneSize)
/// and a parse of the scene file and its meshes. Throws InputError (FileError / ParseError).
SceneSize checkStudyScene(const std::string& path, int width = 0, int height = 0, int maxSize = 0, int longSide = 0);

/// Parses and prepares a scene at studySceneSize(...), with its acceleration structure and tracer. Throws
/// InputError, also when no size is known.
std::unique_ptr<StudyScene> loadStudyScene(const std::string& path, int width = 0, int height = 0,
                                           int maxSize = 0, int longSide = 0);

}  // namespace aliaslab
