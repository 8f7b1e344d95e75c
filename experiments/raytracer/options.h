// The `raytracer` command line: the classic course flags (single dash,
// scenes/README.md) plus aliaslab's general ones (double dash).
//
// CLI11 only takes single-character names after one dash, so the classic
// long flags are registered as `--input`, `--size`, ... and the command line
// is translated first (`-input` -> `--input`); messages print them back with
// one dash.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace aliaslab {

struct RaytracerOptions {
  // Scene and output.
  std::string input;            ///< -input file: the scene (required)
  std::vector<int> size;        ///< -size w h: image size in pixels, each 1..16384 (required)
  std::string output;           ///< -output file: .png/.tga (8-bit, truncated) or .exr (float)
  // Tracing.
  bool shadows = false;         ///< -shadows
  int bounces = 0;              ///< -bounces n: maximum reflection/refraction depth, >= 0
  float weight = 0.f;           ///< -weight w: cut-off of the accumulated ray weight, >= 0
  bool shadeBack = false;       ///< -shade_back
  std::vector<int> grid;        ///< -grid nx ny nz: grid resolution (default: automatic)
  bool bruteForce = false;      ///< --brute-force: no grid
  // Auxiliary images.
  std::vector<std::string> depth;  ///< -depth dmin dmax file
  std::string normals;             ///< -normals file
  bool stats = false;              ///< -stats: ray counts, accelerator and timing on stdout
  int threads = 0;                 ///< --threads N: 0 = all cores; images do not depend on it
  // Frames (docs/science.md, "Motion"): -frames F writes F colour images, frame t with the camera moved by
  // t (dx, dy) pixels (-motion dx,dy; default 0,0), named by framePath(-output, t).
  int frames = 0;                  ///< -frames F: 0 = one image at -output (the classic behaviour)
  std::vector<double> motion;      ///< -motion dx,dy in pixels per frame
  bool registerFrames = false;     ///< -register: frame t written moved by +t (dx, dy) (measure/registration.h)
  // Classic sampling (imply classic reconstruction).
  int randomSamples = 0, uniformSamples = 0, jitteredSamples = 0;  ///< -<kind>_samples n
  float boxFilter = 0.f, tentFilter = 0.f, gaussianFilter = 0.f;  ///< radius r, r, sigma
  std::vector<std::string> renderSamples;  ///< -render_samples file zoom
  std::vector<std::string> renderFilter;   ///< -render_filter file zoom
  // General sampling.
  std::string sampler;                   ///< --sampler NAME (default: pixel centre)
  int spp = 0;                           ///< --spp N (default 1)
  std::string filter;                    ///< --filter NAME (default: box 0.5 when spp > 1, see sampling_plan.h)
  float radius = 0.f;                    ///< --radius R in pixels (default: defaultFilterRadius)
  uint64_t seed = 0;                     ///< --seed S (default 0)
  std::vector<std::string> filterParams; ///< --filter-param name=value, repeatable
  std::string prefilter = "none";        ///< --prefilter none|footprint
  std::string reconstruction;            ///< --reconstruction weighted|classic|importance|supersample
};

/// Registers every option on `app`, bound to `o`.
void addRaytracerOptions(CLI::App& app, RaytracerOptions& o);

/// argv with the classic single-dash flags turned into double-dash ones.
std::vector<std::string> translateClassicFlags(int argc, char** argv);

/// A CLI11 message with double-dash classic flags turned back into single-dash ones.
std::string classicMessage(std::string message);

/// The file of frame t of -output: "<stem>_<t, 4 digits>.<ext>", e.g. out.png -> out_0003.png.
std::string framePath(const std::string& output, int frame);

/// Checks values, files and folders before any work; throws OptionError
/// naming the option, or FileError for an unreadable input.
void validateRaytracerOptions(const CLI::App& app, const RaytracerOptions& o);

}  // namespace aliaslab
