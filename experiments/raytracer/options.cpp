#include "options.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "../common/cli.h"  // relative: tests/fuzz_regression_test.cpp and fuzz_cli compile this file too
#include "core/error.h"
#include "core/files.h"
#include "core/image.h"
#include "filter/filter.h"
#include "render/tracer.h"
#include "sampling/sampler.h"
#include "study/config.h"

namespace aliaslab {
namespace {

const char* const kClassicFlags[] = {"input",          "size",           "output",          "shadows",
                                     "bounces",        "weight",         "shade_back",      "grid",
                                     "depth",          "normals",        "stats",           "random_samples",
                                     "uniform_samples", "jittered_samples", "box_filter",    "tent_filter",
                                     "gaussian_filter", "render_samples", "render_filter", "frames",
                                     "motion",         "register"};

/// An output image path: supported extension, existing writable folder.
void checkOutput(const std::string& option, const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) throw OptionError(option, "needs a file name");
  if (!isSupportedImageExtension(path))
    throw OptionError(option, "'" + path + "': unsupported image extension (use .png, .tga or .exr)");
  fs::path dir = fs::path(path).parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw OptionError(option, "'" + path + "': folder '" + dir.string() + "' does not exist");
  if (::access(dir.c_str(), W_OK) != 0)
    throw OptionError(option, "'" + path + "': folder '" + dir.string() + "' is not writable");
  if (fs::is_directory(path, ec)) throw OptionError(option, "'" + path + "' is a folder");
}

/// "file zoom" pairs of -render_samples / -render_filter.
void checkZoomed(const std::string& option, const std::vector<std::string>& v) {
  if (v.empty()) return;
  checkOutput(option, v[0]);
  int zoom = 0;
  try {
    size_t used = 0;
    zoom = std::stoi(v[1], &used);
    if (used != v[1].size()) zoom = 0;
  } catch (const std::exception&) {
    zoom = 0;
  }
  if (zoom < 1 || zoom > 256) throw OptionError(option, "zoom must be a whole number in 1..256, found '" + v[1] + "'");
}

}  // namespace

void addRaytracerOptions(CLI::App& app, RaytracerOptions& o) {
  app.add_option("--input", o.input, "scene file (classic course format)")->required();
  app.add_option("--size", o.size, "image width and height in pixels")->expected(2)->required();
  app.add_option("--output", o.output, "image file: .png, .tga (8-bit) or .exr (float)");
  app.add_flag("--shadows", o.shadows, "cast shadow rays");
  app.add_option("--bounces", o.bounces, "maximum reflection/refraction depth (default 0)");
  app.add_option("--weight", o.weight, "stop rays whose accumulated weight falls below w (default 0)");
  app.add_flag("--shade_back", o.shadeBack, "shade back faces like front faces");
  app.add_option("--grid", o.grid, "use a uniform grid of nx ny nz cells (default: a BVH for scenes with triangles, else an automatic grid)")->expected(3);
  app.add_flag("--brute-force", o.bruteForce, "test every primitive instead of using the grid");
  app.add_option("--depth", o.depth, "depth image: dmin dmax file")->expected(3);
  app.add_option("--normals", o.normals, "normal image file");
  app.add_flag("--stats", o.stats, "print ray counts, accelerator and timing");
  app.add_option("--threads", o.threads, "worker threads, 0 = all cores (images do not depend on it)");
  app.add_option("--frames", o.frames,
                 "render F frames of a camera moving by -motion pixels per frame parallel to the image plane; "
                 "frame t goes to <output stem>_<t as 4 digits>.<ext> (out.png: out_0000.png, out_0001.png, ...)");
  app.add_option("--motion", o.motion, "dx,dy: the camera's motion in pixels per frame (default 0,0; needs -frames)")
      ->delimiter(',')
      ->expected(2);
  app.add_flag("--register", o.registerFrames,
               "with -frames: write frame t moved back by t (dx, dy) pixels onto frame 0's content (the library's "
               "band-limited shift, docs/science.md \"Motion\"): what still changes is shimmer and noise");
  // Classic sampling.
  app.add_option("--random_samples", o.randomSamples, "n independent uniform samples per pixel");
  app.add_option("--uniform_samples", o.uniformSamples, "n samples on a regular grid per pixel");
  app.add_option("--jittered_samples", o.jitteredSamples, "n jittered samples per pixel");
  app.add_option("--box_filter", o.boxFilter, "box filter, r = centre to edge distance in pixels");
  app.add_option("--tent_filter", o.tentFilter, "tent (cone) filter of radius r pixels");
  app.add_option("--gaussian_filter", o.gaussianFilter, "Gaussian filter of standard deviation sigma pixels");
  app.add_option("--render_samples", o.renderSamples, "sample visualisation: file zoom")->expected(2);
  app.add_option("--render_filter", o.renderFilter,
                 "filter weight picture: file zoom (classic flags: the course picture; otherwise the filter as "
                 "used, red positive, blue negative, with a colour bar)")
      ->expected(2);
  // General sampling.
  std::string samplers, filters;
  for (const std::string& n : samplerNames()) samplers += (samplers.empty() ? "" : ", ") + n;
  for (const std::string& w : samplerWrapperNames()) samplers += ", " + w + ":BASE (any of these)";
  for (const std::string& n : filterNames()) filters += (filters.empty() ? "" : ", ") + n;
  app.add_option("--sampler", o.sampler,
                 "sampler: " + samplers + "; or adaptive-contrast|adaptive-error|adaptive-subdiv:BASE (docs/adaptive.md)");
  app.add_option("--spp", o.spp, "samples per pixel (default 1)");
  app.add_option("--filter", o.filter,
                 "reconstruction filter: " + filters +
                     ", as in the studies (gaussian: sigma = radius / 3); or course-gaussian, the course's Gaussian "
                     "(fixed sigma 0.5, uncut on its square support), or gaussian-cut (fixed sigma 0.5, cut at the "
                     "radius) (default: with --spp above 1 the pixel-area box of radius 0.5, weighted; with 1 "
                     "sample the sample itself)");
  app.add_option("--radius", o.radius,
                 "filter support radius in pixels (default: the filter's natural support: box 0.5, tent 1, "
                 "gaussian 1.5 (3 sigma when a sigma is given), mitchell/catmullrom/blackmanharris 2, lanczos/hann "
                 "tau, course-gaussian ceil(2 sigma - 1/2) + 1/2, gaussian-cut 3 sigma)");
  app.add_option("--seed", o.seed, "random seed (default 0)")->check(kSeed);
  app.add_option("--filter-param", o.filterParams,
                 "filter shape parameters name=value, comma-separated or repeated (defaults: gaussian sigma=0, "
                 "i.e. radius / 3, subtract_edge=0; course-gaussian and gaussian-cut sigma=0.5; mitchell B=C=1/3; "
                 "lanczos and hann tau=3)")
      ->delimiter(',');
  app.add_option("--reconstruction", o.reconstruction, "weighted, classic, importance or supersample");
  app.add_option("--prefilter", o.prefilter,
                 "none or footprint: average textures over each sample's footprint (1/sqrt(spp) pixels a side; "
                 "docs/prefiltering.md)");
  app.footer("The classic flags take one dash as in the course (-input, -size, ...) or two.");
}

std::vector<std::string> translateClassicFlags(int argc, char** argv) {
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    for (const char* flag : kClassicFlags)
      if (a == std::string("-") + flag) a = "-" + a;
    // A file name that is really the next flag ("-input -size 9 9"): say so, not "-size is required".
    const bool takesFile = a == "--input" || a == "--output" || a == "--normals";
    if (takesFile && i + 1 < argc) {
      const std::string next = argv[i + 1];
      for (const char* flag : kClassicFlags)
        if (next == std::string("-") + flag || next == std::string("--") + flag)
          throw OptionError(a.substr(1), "needs a file name, found the flag '" + next + "'");
    }
    args.push_back(a);
  }
  return args;
}

std::string classicMessage(std::string message) {
  for (const char* flag : kClassicFlags) {
    const std::string dd = std::string("--") + flag;
    for (size_t p = message.find(dd); p != std::string::npos; p = message.find(dd, p + 1)) {
      const size_t end = p + dd.size();
      const bool whole = end == message.size() || !(std::isalnum(static_cast<unsigned char>(message[end])) ||
                                                      message[end] == '_' || message[end] == '-');
      if (whole) message.erase(p, 1);
    }
  }
  return message;
}

std::string framePath(const std::string& output, int frame) {
  const std::filesystem::path p(output);
  char number[16];
  std::snprintf(number, sizeof number, "_%04d", frame);
  return (p.parent_path() / (p.stem().string() + number + p.extension().string())).string();
}

std::vector<OutputFile> writtenFiles(const RaytracerOptions& o) {
  std::vector<OutputFile> files;
  if (o.frames > 0)
    for (int t = 0; t < o.frames; ++t) files.push_back({"-output", framePath(o.output, t)});  // -output names the frames
  else if (!o.output.empty())
    files.push_back({"-output", o.output});
  if (!o.normals.empty()) files.push_back({"-normals", o.normals});
  if (!o.depth.empty()) files.push_back({"-depth", o.depth[2]});
  if (!o.renderSamples.empty()) files.push_back({"-render_samples", o.renderSamples[0]});
  if (!o.renderFilter.empty()) files.push_back({"-render_filter", o.renderFilter[0]});
  return files;
}

void validateRaytracerOptions(const CLI::App& app, const RaytracerOptions& o) {
  namespace fs = std::filesystem;
  // Image size and tracing parameters.
  const int w = o.size[0], h = o.size[1];
  if (w < 1 || h < 1 || w > 16384 || h > 16384)
    throw OptionError("-size", "width and height must be in 1..16384, found " + std::to_string(w) + " " +
                                   std::to_string(h));
  if (o.bounces < 0 || o.bounces > kMaxBounces)
    throw OptionError("-bounces", "must be in 0.." + std::to_string(kMaxBounces));
  if (!(o.weight >= 0.f) || !std::isfinite(o.weight)) throw OptionError("-weight", "must be finite and >= 0");
  if (o.threads < 0) throw OptionError("--threads", "must be >= 0 (0 = all cores)");
  parsePrefilter(o.prefilter);
  if (!o.grid.empty()) {
    if (o.bruteForce) throw OptionError("-grid", "cannot be combined with --brute-force");
    double cells = 1;
    for (int n : o.grid) {
      if (n < 1 || n > 1024) throw OptionError("-grid", "each resolution must be in 1..1024");
      cells *= n;
    }
    if (cells > double(1 << 27)) throw OptionError("-grid", "more than 2^27 cells");
  }

  // Frames: a count, a finite motion, the colour image only.
  if (app.count("--frames") && (o.frames < 1 || o.frames > 10000))
    throw OptionError("-frames", "must be a whole number in 1..10000, found " + std::to_string(o.frames));
  if (!o.motion.empty()) {
    if (!app.count("--frames")) throw OptionError("-motion", "needs -frames (the number of frames to render)");
    for (double v : o.motion)
      if (!std::isfinite(v) || std::abs(v) > 1e6)
        throw OptionError("-motion", "dx and dy must be finite numbers of pixels per frame (at most 1e6)");
  }
  if (o.registerFrames && !app.count("--frames"))
    throw OptionError("-register", "needs -frames (it registers the frames to frame 0's content)");
  if (o.frames > 0) {
    if (o.output.empty()) throw OptionError("-frames", "needs -output (its name gives the frames' names)");
    if (!o.depth.empty() || !o.normals.empty() || !o.renderSamples.empty() || !o.renderFilter.empty())
      throw OptionError("-frames", "renders the colour image only; drop -depth, -normals, -render_samples and "
                                   "-render_filter");
  }

  // Outputs: at least one, each writable.
  if (!o.output.empty()) checkOutput("-output", o.output);
  if (!o.normals.empty()) checkOutput("-normals", o.normals);
  if (!o.depth.empty()) {
    float dmin = 0, dmax = 0;
    try {
      dmin = std::stof(o.depth[0]);
      dmax = std::stof(o.depth[1]);
    } catch (const std::exception&) {
      throw OptionError("-depth", "dmin and dmax must be numbers, found '" + o.depth[0] + "' '" + o.depth[1] + "'");
    }
    if (!std::isfinite(dmin) || !std::isfinite(dmax) || !(dmax > dmin))
      throw OptionError("-depth", "needs finite dmin < dmax");
    checkOutput("-depth", o.depth[2]);
  }
  checkZoomed("-render_samples", o.renderSamples);
  checkZoomed("-render_filter", o.renderFilter);
  for (const auto* v : {&o.renderSamples, &o.renderFilter})
    if (!v->empty() && (double(w) * std::stoi((*v)[1]) > 16384 || double(h) * std::stoi((*v)[1]) > 16384))
      throw OptionError(v == &o.renderSamples ? "-render_samples" : "-render_filter",
                        "the zoomed image (size x zoom) must be at most 16384 on each side, like -size; found " +
                            std::to_string(w) + " x " + std::to_string(h) + " at zoom " + (*v)[1]);
  // Every file written its own (one would silently overwrite another), and none the scene (its OBJ files: main).
  refuseOutputsOverInputs(writtenFiles(o), {o.input});
  if (o.output.empty() && o.normals.empty() && o.depth.empty() && o.renderSamples.empty() && o.renderFilter.empty())
    throw OptionError("-output", "nothing to write: give -output, -depth, -normals, -render_samples or -render_filter");

  // The scene file must be readable.
  std::error_code ec;
  requireRegularFile(o.input, "a scene is read from a regular file (-input)");  // a FIFO would block the reader
  if (!fs::is_regular_file(o.input, ec) || ::access(o.input.c_str(), R_OK) != 0)
    throw FileError(o.input, "cannot open the scene file (-input)");
}

}  // namespace aliaslab
