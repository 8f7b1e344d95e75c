#include "study/validate.h"

#include <unistd.h>
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "core/files.h"
#include "core/format.h"
#include "core/memory_limit.h"
#include "filter/filter.h"
#include "measure/registration.h"
#include "render/sample_source.h"
#include "sampling/sampler.h"
#include "study/sweep/alignment.h"
#include "study/records/csv.h"
#include "study/records/lock.h"
#include "study/records/spectrum_files.h"
#include "study/study_scene.h"
#include "study/sweep/sweep_memory.h"

namespace aliaslab {

namespace fs = std::filesystem;

namespace {
std::string formatValue(const std::string& s) { return "'" + s + "'"; }
std::string formatValue(int v) { return std::to_string(v); }
std::string formatValue(double v) { return formatNumber(v); }

// The folders a validation created (deepest last), removed again when a later check fails.
class NewFolders {
 public:
  ~NewFolders() {
    if (keep_) return;
    std::error_code ec;
    for (auto it = made_.rbegin(); it != made_.rend(); ++it) fs::remove(*it, ec);  // only if still empty
  }
  /// `dir` exists and is writable afterwards, or OptionError(key); remembers what it had to create.
  void require(const std::string& dir, const std::string& key) {
    std::vector<fs::path> missing;
    std::error_code ec;
    for (fs::path p = fs::absolute(dir, ec).lexically_normal(); !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
      missing.push_back(p);
      if (p == p.parent_path()) break;
    }
    fs::create_directories(dir, ec);
    for (auto it = missing.rbegin(); it != missing.rend(); ++it)
      if (fs::is_directory(*it, ec)) made_.push_back(*it);
    if (!fs::is_directory(dir, ec)) throw OptionError(key, "cannot create folder '" + dir + "'");
    if (::access(dir.c_str(), W_OK) != 0) throw OptionError(key, "folder '" + dir + "' is not writable");
  }
  /// Every check passed: keep the folders.
  void keep() { keep_ = true; }

 private:
  std::vector<fs::path> made_;
  bool keep_ = false;
};

/// The lists and numbers of the configuration, in the order the user reads them.
void checkListsAndNumbers(const StudyConfig& c) {
  if (c.samplers.empty()) throw OptionError("samplers", "needs at least one sampler");
  if (c.filters.empty()) throw OptionError("filters", "needs at least one filter");
  if (c.spp.empty()) throw OptionError("spp", "needs at least one sample count");
  if (c.radii.empty() && !c.naturalRadii) throw OptionError("radii", "needs at least one radius or 'natural'");
  if (c.reconstruction.empty()) throw OptionError("reconstruction", "needs at least one mode");
  if (c.prefilter.empty()) throw OptionError("prefilter", "needs at least one of none, footprint");
  for (const std::string& p : c.prefilter) parsePrefilter(p);
  for (size_t i = 0; i < c.prefilter.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (c.prefilter[i] == c.prefilter[j]) throw OptionError("prefilter", "'" + c.prefilter[i] + "' given twice");
  if (c.scenes.empty()) throw OptionError("scenes", "needs at least one scene file or folder");
  if (c.seeds < 2) throw OptionError("seeds", "needs K >= 2 (noise is a variance over seeds), found " +
                                                    std::to_string(c.seeds));
  // The reference options: one check (study/reference/reference.h), the same as the reference front end's.
  rekeyOption("sampler", "ref-sampler", [&] { validateReferenceOptions(referenceOptions(c)); });
  if (c.alignOffsets < 0 || c.alignOffsets > 4096)
    throw OptionError("align-offsets", "must be in 0..4096 (0: no alignment columns), found " +
                                           std::to_string(c.alignOffsets));
  if (c.alignOffsets == 1)
    throw OptionError("align-offsets", "needs K >= 2 offsets (their spread is measured) or 0 for none");
  if (c.alignOffsets > 0)
    rekeyOption("ref-spp", "align-ref-spp", [&] {
      rekeyOption("sampler", "ref-sampler", [&] { validateReferenceOptions(alignmentReferenceOptions(c)); });
    });
  if (c.threads < 0) throw OptionError("threads", "must be >= 0");
  if (c.frames < 1 || c.frames > 1000)
    throw OptionError("frames", "must be in 1..1000 (1: a still study), found " + std::to_string(c.frames));
  if (!std::isfinite(c.motionDx) || !std::isfinite(c.motionDy) || std::abs(c.motionDx) > 1e4 ||
      std::abs(c.motionDy) > 1e4)
    throw OptionError("motion", "dx and dy must be finite numbers of pixels per frame (at most 1e4)");
  if (c.motionGiven && c.frames == 1)
    throw OptionError("motion", "needs frames F > 1: a still study (one frame) has no motion");
  if ((c.width > 0) != (c.height > 0) || c.width < 0 || c.height < 0)
    throw OptionError("size", "expected two positive numbers W H");
  if (c.maxSize < 0) throw OptionError("max-size", "must be >= 0");
  if (c.longSide < 0) throw OptionError("long-side", "must be >= 0");
}

/// No name or number listed twice, no two radii the CSV writes alike, counts and radii in range, every name
/// known to its factory.
void checkListEntries(const StudyConfig& c) {
  // A name or number listed twice would make every configuration of it twice (the CSV keeps one).
  auto once = [](const auto& list, const char* key) {
    for (size_t i = 0; i < list.size(); ++i)
      for (size_t j = i + 1; j < list.size(); ++j)
        if (list[i] == list[j]) throw OptionError(key, "lists " + formatValue(list[i]) + " twice");
  };
  once(c.samplers, "samplers"), once(c.spp, "spp"), once(c.filters, "filters"), once(c.radii, "radii");
  once(c.reconstruction, "reconstruction");
  // Radii are the CSV's key in its text (%.9g): two radii written alike would be one row for two configurations.
  for (size_t i = 0; i < c.radii.size(); ++i)
    for (size_t j = i + 1; j < c.radii.size(); ++j)
      if (formatReal(c.radii[i]) == formatReal(c.radii[j]))
        throw OptionError("radii", "lists " + formatNumber(c.radii[i], "%.17g") + " and " +
                                       formatNumber(c.radii[j], "%.17g") + ", which the CSV writes alike (" +
                                       formatReal(c.radii[i]) + ")");
  for (int spp : c.spp)
    if (spp < 1) throw OptionError("spp", "sample counts must be >= 1, found " + std::to_string(spp));
  for (double r : c.radii)
    if (!(std::isfinite(r) && r > 0)) throw OptionError("radii", "radii must be finite and > 0, found " +
                                                                      formatNumber(r));
  // Names: the factories' own messages list the valid ones.
  for (const std::string& m : c.reconstruction) parseReconMode(m);
  for (const std::string& s : c.samplers)
    for (int spp : c.spp)
      rekeyOption("sampler", "samplers", [&] { makeSampleSource(s, spp, 0); });
}

/// Memory for `path` at `size`, before any allocation: the scheduler's bound for the largest group
/// (rowsPerGroup rows, weightedRows of them weighted averages) at the largest spp, plus the references.
void checkSceneMemory(const StudyConfig& c, const std::string& path, const SceneSize& size, size_t rowsPerGroup,
                      size_t weightedRows) {
  // per reference: its mean and half-difference images and a pass's 4 sums (the filters, the area and the targets)
  const double references =
      double(studyFilters(c).size() + c.targets.size() + 1) * (6 * sizeof(float) + 4 * sizeof(double));
  const size_t referenceCount = studyFilters(c).size() + c.targets.size() + 1;
  const int maxSpp = *std::max_element(c.spp.begin(), c.spp.end());
  const double pixels = double(size.width) * size.height;
  // with frames (study/sweep/sweep_motion.h): each row's K x F images and every later frame's reference images
  const double image = double(imageBytes(size.width, size.height));
  // the fixed grid's alignment: the targets' references at every offset, held for the scene
  const double offsets = double(c.alignOffsets) * pixels * double(c.targets.size()) * 6 * sizeof(float);
  // (later frames render the targets' references only)
  const double frames = c.frames > 1 ? double(rowsPerGroup) * c.seeds * c.frames * image +
                                           (c.frames - 1) * pixels * double(c.targets.size() + 1) * 6 * sizeof(float)
                                     : 0.0;
  if (c.frames > 1 && std::min(size.width, size.height) <= 2 * registrationMargin(c.motionDx, c.motionDy))
    throw OptionError("motion", fs::path(path).stem().string() + " at " + std::to_string(size.width) + " x " +
                                    std::to_string(size.height) + " has no pixel " +
                                    std::to_string(registrationMargin(c.motionDx, c.motionDy)) +
                                    " pixels from its border, where shimmer is measured (the motion per frame "
                                    "plus the registration's margin, docs/science.md \"Motion\")");
  const std::string framesWhat =
      c.frames > 1 ? " with " + std::to_string(c.frames) + " frames (" + std::to_string(rowsPerGroup) + " rows x " +
                         std::to_string(c.seeds) + " seeds x " + std::to_string(c.frames) +
                         " frames of images held per group)"
                   : "";
  requireMemory(offsets + frames + double(sweepMemoryBound(c.threads, size.width, size.height, maxSpp, rowsPerGroup,
                                                 weightedRows, c.seeds)) +
                    std::max(pixels * references,
                             referenceMemoryBytes(size.width, size.height, referenceCount, referenceOptions(c))),
                c.frames > 1 ? "frames" : "size",
                fs::path(path).stem().string() + " at " + std::to_string(size.width) + " x " +
                    std::to_string(size.height) + " and " + std::to_string(maxSpp) + " spp" + framesWhat);
}

}  // namespace

StudyPlan validateStudy(const StudyConfig& c) {
  StudyPlan plan;
  checkListsAndNumbers(c);
  plan.targets = parseTargets(c.targets, plan.filters);
  plan.area = plan.filters.get(kAreaSpec);
  checkListEntries(c);
  // The groups, every (filter, radius) built here once (the factory names the valid filters).
  rekeyOption("filter", "filters", [&] {
    rekeyOption("radius", "radii", [&] { plan.groups = expandStudy(c, plan.filters, &plan.notes); });
  });

  // Scenes: present and parseable, with a known size; never the CSV this run writes.
  // Memory is per group (the sweep holds one group's seeds in flight, study/sweep/sweep_memory.h sweepMemoryBound),
  // plus the scene's reference images and the reference pass's sums: the largest group decides.
  size_t rowsPerGroup = 0, weightedRows = 0;
  for (const SampleSetGroup& g : plan.groups) {
    rowsPerGroup = std::max(rowsPerGroup, g.configs.size());
    weightedRows = std::max<size_t>(weightedRows, std::count_if(g.configs.begin(), g.configs.end(), [](const Configuration& x) {
                                      return x.mode == ReconMode::WeightedAverage;
                                    }));
  }
  // No file the run writes may be a scene: the CSV, its lock, and per scene its spectra and reference manifest.
  const std::vector<std::string> scenePaths = expandScenePaths(c.scenes);
  std::vector<OutputFile> outputs;
  if (!c.refsOnly) outputs = {{"csv", csvPath(c)}, {"csv", CsvLock::lockPath(csvPath(c))}};
  for (const std::string& path : scenePaths) {
    const std::string stem = fs::path(path).stem().string();
    if (!c.refsOnly) outputs.push_back({"csv", spectrumCsvPath(csvPath(c), stem)});
    outputs.push_back({"out", (fs::path(c.out) / "references" / (stem + ".json")).string()});
  }
  refuseOutputsOverInputs(outputs, scenePaths);
  for (const std::string& path : scenePaths) {
    requireRegularFile(path, "a scene is read from a regular file");
    if (!fs::is_regular_file(path)) throw FileError(path, "scene file not found");
    const SceneSize size = plan.sceneSizes[path] = checkStudyScene(path, c.width, c.height, c.maxSize, c.longSide);
    checkSceneMemory(c, path, size, rowsPerGroup, weightedRows);
  }

  // Outputs that must be regular files (a FIFO would block, a folder cannot be appended to): refused up front.
  if (!c.refsOnly)
    requireRegularFile(csvPath(c), "a study CSV is a regular file (it is read, resumed and appended to); give "
                                   "another {csv} or {out}");
  // Output folders: all or none (a failed check removes the folders made before it).
  requireOutputFolders({{c.out, "out"}, {fs::path(csvPath(c)).parent_path().string(), "csv"}, {c.cache, "cache"}});
  return plan;
}

void requireOutputFolders(const std::vector<std::pair<std::string, std::string>>& folders) {
  NewFolders made;
  for (const auto& [dir, key] : folders) made.require(dir.empty() ? "." : dir, key);
  made.keep();
}


namespace {
// The value of column `name` in a parsed row.
const std::string& field(const std::vector<std::string>& f, const std::string& name) {
  const auto& cols = csvColumns();
  return f[static_cast<size_t>(std::find(cols.begin(), cols.end(), name) - cols.begin())];
}
std::string sameStudyAdvice() {
  return ". A study CSV holds one study: rerun with the options it was made with to resume it, or give another "
         "{out} or {csv} for the new study";
}
}  // namespace

void checkSameStudy(const std::string& csv, const std::vector<std::string>& lines, const StudyConfig& c,
                    const std::vector<Target>& targets) {
  const std::pair<const char*, const char*> studyWide[] = {{"seeds", "seeds"}, {"ref_spp", "ref-spp"}};
  const std::string wanted[] = {std::to_string(c.seeds), std::to_string(c.refSpp)};
  for (size_t i = 0; i < lines.size(); ++i) {
    const auto f = splitCsvLine(lines[i]);
    if (!isStudyRow(f)) continue;
    for (size_t k = 0; k < std::size(studyWide); ++k)
      if (field(f, studyWide[k].first) != wanted[k])
        throw OptionError(studyWide[k].second, csv + " holds a study made with " + studyWide[k].first + " " +
                                                   field(f, studyWide[k].first) + " (data row " +
                                                   std::to_string(i + 1) + "); this run asks for " + wanted[k] +
                                                   sameStudyAdvice());
    // So are the fixed grid's alignment offsets (empty cells: none).
    const std::string offsets = c.alignOffsets > 0 ? std::to_string(c.alignOffsets) : "";
    if (field(f, "sampler") == kFixedGridSampler && field(f, "align_offsets") != offsets)
      throw OptionError("align-offsets", csv + " holds a study made with " +
                                             (field(f, "align_offsets").empty() ? std::string("no alignment offsets")
                                                                                : field(f, "align_offsets") + " alignment offsets") +
                                             " (data row " + std::to_string(i + 1) + "); this run asks for " +
                                             (offsets.empty() ? std::string("none") : offsets) + sameStudyAdvice());
    // Frames and motion are study-wide too (the CsvAppender refuses a still CSV for a study with frames).
    const size_t m = csvColumns().size();
    if (f.size() > m && (f[m] != std::to_string(c.frames) || f[m + 1] != formatReal(c.motionDx) ||
                         f[m + 2] != formatReal(c.motionDy)))
      throw OptionError(f[m] != std::to_string(c.frames) ? "frames" : "motion",
                        csv + " holds a study made with " + f[m] + " frames and motion " + f[m + 1] + "," +
                            f[m + 2] + " (data row " + std::to_string(i + 1) + ")" + sameStudyAdvice());
  }
  // The targets are study-wide too: every configuration has one row per target, so another list would add a
  // second set of rows to the same configurations (and change which target is primary).
  std::vector<std::string> held, asked;
  for (const Target& t : targets) asked.push_back(t.label);
  for (const std::string& l : lines) {
    const auto f = splitCsvLine(l);
    if (isStudyRow(f) && std::find(held.begin(), held.end(), field(f, "target")) == held.end())
      held.push_back(field(f, "target"));
  }
  auto sorted = [](std::vector<std::string> v) { return std::sort(v.begin(), v.end()), v; };
  auto joined = [](const std::vector<std::string>& v) {
    std::string s;
    for (const std::string& x : v) s += (s.empty() ? "" : ",") + x;
    return s;
  };
  if (!held.empty() && sorted(held) != sorted(asked))
    throw OptionError("target", csv + " holds a study made with the targets " + joined(sorted(held)) +
                                    "; this run asks for " + joined(sorted(asked)) + sameStudyAdvice());
}

void checkSameSceneSize(const std::string& csv, const std::vector<std::string>& lines, const std::string& stem,
                        int width, int height) {
  for (size_t i = 0; i < lines.size(); ++i) {
    const auto f = splitCsvLine(lines[i]);
    if (!isStudyRow(f) || field(f, "scene") != stem) continue;
    if (field(f, "width") != std::to_string(width) || field(f, "height") != std::to_string(height))
      throw OptionError("size", csv + " holds scene " + stem + " at " + field(f, "width") + " x " +
                                      field(f, "height") + " (data row " + std::to_string(i + 1) +
                                      "); this run renders it at " + std::to_string(width) + " x " +
                                      std::to_string(height) + " ({size} / {max-size})" + sameStudyAdvice());
  }
}

}  // namespace aliaslab
