// The `# render:` line: the one machine-readable comment of an aliaslab scene file, saying how the study tools
// render the scene (the classic raytracer takes the same settings from its command line and ignores the line):
//   # render: -size W H [-shadows] [-bounces n] [-weight w] [-shade_back] [-grid nx ny nz]
// The scene parser reads it as scene data (Scene::render), with the line breaks it reads ("\n", "\r\n", a lone
// "\r"). The first line holding "# render:" counts. A malformed one is a ParseError "<file>:<line>: render line:
// ..." (an unknown keyword, a missing or non-numeric value, -size not positive, -bounces outside 0..kMaxBounces,
// a negative -grid resolution, no -size).
#pragma once
#include <string>

namespace aliaslab {

/// The most reflection/refraction bounces a ray may take (the render line's -bounces, the raytracer's too).
inline constexpr int kMaxBounces = 256;

/// What a render line says; all defaults (found false) when the scene has none.
struct RenderSettings {
  int width = 0, height = 0;  ///< -size W H
  bool shadows = false;       ///< -shadows: cast shadow rays
  int bounces = 0;            ///< -bounces n: reflection/refraction depth
  float weight = 0.f;         ///< -weight w: stop a ray whose accumulated weight falls below w
  bool shadeBack = false;     ///< -shade_back: shade back faces with the flipped normal
  int grid[3] = {0, 0, 0};    ///< -grid nx ny nz: the uniform grid's resolution (0: automatic)
  bool found = false;         ///< false when the scene has no render line
  int line = 0;               ///< its line in the scene file (0: none)
};

/// The render line of scene text `text`; `file` names the scene in messages. Throws ParseError.
RenderSettings parseRenderLine(const std::string& text, const std::string& file);

}  // namespace aliaslab
