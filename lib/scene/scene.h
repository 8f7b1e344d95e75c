// A parsed scene: everything a scene file declares.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "geometry/primitives.h"
#include "scene/camera.h"
#include "scene/light.h"
#include "scene/material.h"
#include "scene/render_settings.h"

namespace aliaslab {

struct Scene {
  std::unique_ptr<Camera> camera;
  Color background = Color::Constant(0.5f);  ///< Background color, default grey 0.5
  Color ambient = Color::Zero();             ///< Background ambientLight, default black
  std::vector<std::unique_ptr<Light>> lights;
  std::vector<std::unique_ptr<Material>> materials;  ///< procedurals point at earlier entries
  std::unique_ptr<Group> root;                       ///< the top-level Group
  std::string path;                                  ///< the scene file as given
  std::vector<std::string> dependencies;             ///< resolved OBJ paths, for content hashing
  RenderSettings render;                             ///< its `# render:` line (scene/render_settings.h)
};

/// Parses a classic course scene file (scenes/README.md plus
/// the Pattern extension). Throws FileError when it cannot be read and
/// ParseError "<file>:<line>: <what was expected>" for malformed content,
/// including malformed OBJ files (which name the OBJ file and its line) and
/// a malformed `# render:` line (read first).
Scene parseScene(const std::string& path);

/// The same from text; `name` is used in messages and `baseDir` to resolve OBJ files.
Scene parseSceneText(const std::string& text, const std::string& name, const std::string& baseDir);

}  // namespace aliaslab
