// What a sweep measures, and the list of configurations it expands to.
//
// A StudyConfig is the cross product scenes x samplers x spp x prefilter x
// filters x radii x reconstruction modes, each configuration rendered with K
// seeds. expandStudy() turns it into SampleSetGroups: one group per (scene,
// sampler, spp, prefilter), whose K sample sets (one per seed) are traced once and
// reconstructed with every (filter, radius) of the group. Groups and the
// configurations inside them come in a fixed canonical order, so a shard
// (shard i of N: groups g with g mod N == i) is deterministic and keeps the
// reuse of traced samples. Checking a config before any work is
// study/validate.h; merging the shards' CSVs is study/records/merge.h; the bundled
// studies are study/presets.h.
//
// Errors are InputError: OptionError keyed by the StudyConfig field it is
// about ("samplers", "radii", "ref-spp": the field's name, dashes for
// camelCase), FileError naming the file. Front ends map keys to their flags.
//
// Built once, passed down: every distinct (filter, radius) of a study is made once by the study's FilterCache
// (study/filter_cache.h, owned by the StudyPlan) and shared by its configurations, its targets (parsed once with
// their CSV labels: Target, parseTargets) and its references.
//
// Several targets: a study measures every configuration against each target T of `targets` (each only another
// reference from the same samples, rendered in the one reference pass); the CSV has one row per (configuration,
// target). The first target is the primary one.
#pragma once
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "film/film.h"
#include "study/filter_cache.h"
#include "study/reference/reference.h"  // kDefaultReferenceSpp
#include "study/study_scene.h"

namespace aliaslab {

struct StudyConfig {
  std::vector<std::string> scenes;                  ///< scene files (folders expanded to their *.txt)
  std::vector<std::string> samplers = {"random", "uniform", "jittered"};
  std::vector<int> spp = {4, 16};                   ///< samples per pixel, each >= 1
  std::vector<std::string> filters = {"box", "tent", "gaussian"};
  std::vector<double> radii = {0.5, 1.0, 1.5};      ///< support radii in pixels, each > 0
  /// also every filter at its own natural radius (the registry's defaultFilterRadius: box 0.5, tent 1, gaussian
  /// 1.5, mitchell 2, lanczos 3, ...), once when it is already in `radii`; `radii` may then be empty
  bool naturalRadii = false;
  std::vector<std::string> reconstruction = {"weighted"};  ///< weighted|classic|importance|supersample
  /// none|footprint: texture pre-filtering over each hit's pixel footprint
  /// (render/tracer.h); the references are always un-prefiltered.
  std::vector<std::string> prefilter = {"none"};
  bool classicBox = true;   ///< also box at r = 0.5 when box is listed and 0.5 is not a radius
  int seeds = 8;            ///< K independent seeds per configuration (>= 2)
  int refSpp = kDefaultReferenceSpp;       ///< samples per pixel of the references
  int width = 0, height = 0;  ///< size override (0: each scene's `# render:` size)
  int maxSize = 0;          ///< scale each scene down so its larger side is at most this (0: off)
  int longSide = 0;         ///< scale each scene up or down so its larger side is exactly this (0: off)
  /// the targets T (first = primary): "area" (= box:0.5) or "filter:radius"; area, the natural-width Gaussian
  /// (sigma = r/3 = 0.5) and the band-limited Lanczos-windowed sinc with its zeros on integer pixels
  std::vector<std::string> targets = {"area", "gaussian:1.5", "lanczos:3"};
  std::string out = "results/study";  ///< output folder
  std::string csv;          ///< CSV path (default out/study.csv, or out/study.shard-i-of-N.csv); *.gz: gzipped
  std::string cache = "results/cache/refs";  ///< reference cache folder
  int threads = 0;          ///< worker threads (0: all cores)
  std::optional<bool> images;  ///< write images (default: when there are at most 200 configurations)
  int shardIndex = 0, shardCount = 1;  ///< shard i of N
  std::string refSampler = "sobol";  ///< sampler of the references (scrambled low-discrepancy)
  int refBatch = 16;        ///< reference samples per pixel per streamed batch
  bool refsOnly = false;    ///< render and cache the references, then stop (before sharded runs)
  bool progress = true;     ///< progress bar / lines on stderr
  /// Motion (study/sweep/sweep_motion.h): F frames of a camera moving (dx, dy) pixels per frame; F = 1 is a still study
  /// (the CSV without motion columns), F > 1 adds the motion measures to every row.
  int frames = 1;
  double motionDx = 0.25, motionDy = 0;
  /// The fixed grid's alignment (study/sweep/alignment.h; docs/science.md "The grid and alignment"): K seeded sub-pixel
  /// camera offsets, each with the targets' references rendered there, measured on every row of the sampler
  /// `uniform` (0: off, the alignment columns stay empty). alignRefSpp: the offset references' samples per pixel.
  int alignOffsets = 0;
  int alignRefSpp = 1024;
  bool motionGiven = false;  ///< the motion was asked for (refused without frames: a still study has none)
};

/// One row of the CSV before it is measured.
struct Configuration {
  StudyFilter filter;
  ReconMode mode = ReconMode::WeightedAverage;
};

/// A target T of a study, parsed once: its filter (from the study's FilterCache) and the CSV's `target` column.
struct Target {
  StudyFilter filter;  ///< "area" is the pixel-area reference (box, r = 0.5)
  std::string label;   ///< "filter:radius" with the radius in %g ("box:0.5" for "area")
};

/// The K sample sets of one (scene, sampler, spp, prefilter) and the rows made from them.
struct SampleSetGroup {
  int index = 0;          ///< canonical position among all groups (for sharding)
  std::string scene;      ///< scene file path
  std::string sampler;
  int spp = 0;
  std::string prefilter = "none";  ///< none | footprint
  std::vector<Configuration> configs;
};

/// Expands folders in `scenes` into their sorted *.txt files. The same file given twice is kept once; two
/// different files with the same stem (a/s.txt, b/s.txt) are refused (OptionError "scenes"): rows are keyed
/// by the stem.
std::vector<std::string> expandScenePaths(const std::vector<std::string>& scenes);

/// Every group in canonical order (unsharded). Supersample rows exist only
/// for the uniform sampler at square spp (one row, box r = 0.5); notes about
/// skipped combinations are appended to `notes`. Each distinct (filter, radius)
/// comes from `filters` (built once) and is shared by the configurations that use it.
std::vector<SampleSetGroup> expandStudy(const StudyConfig& config, FilterCache& filters,
                                        std::vector<std::string>* notes = nullptr);

/// The groups of this shard.
std::vector<SampleSetGroup> shardGroups(const std::vector<SampleSetGroup>& groups, int index, int count);

/// Checks a pre-filtering name: "none" or "footprint" (the values of the CSV
/// column prefilter); returns whether it asks for pre-filtering. Throws
/// OptionError(key) naming the valid values.
bool parsePrefilter(const std::string& name, const std::string& key = "prefilter");

/// Every distinct (filter, radius) of the study, in canonical order (names only; the FilterCache builds them): per
/// filter the radii in order, box's classic 0.5 first (classicBox), its natural radius last (naturalRadii), each once.
std::vector<FilterSpec> studyFilters(const StudyConfig& config);

/// The radius list of a study from its tokens: each a radius in pixels (finite, > 0) or "natural" (every filter
/// also at its natural radius: naturalRadii). Sets config.radii and config.naturalRadii; throws
/// OptionError("radii") naming a bad token or one given twice.
void setStudyRadii(StudyConfig& config, const std::vector<std::string>& tokens);

/// The tokens of config's radius list (each radius in %g, then "natural"): what setStudyRadii reads back.
std::vector<std::string> studyRadiusTokens(const StudyConfig& config);

/// The target T of a study: "area" is the pixel-area reference (box, r = 0.5);
/// otherwise "filter:radius", e.g. "gaussian:1.5"; its filter comes from `filters`. Throws OptionError("target")
/// naming the valid forms (the factory's refusals re-keyed "target").
Target parseTarget(const std::string& text, FilterCache& filters);

/// The targets of a study, in order (the first is the primary). Throws OptionError("target") for an empty list,
/// an unusable entry (parseTarget) or one given twice ("area" and "box:0.5" are the same target).
std::vector<Target> parseTargets(const std::vector<std::string>& texts, FilterCache& filters);

/// Parses "i/N" (0 <= i < N). Throws OptionError("shard").
void parseShard(const std::string& text, int& index, int& count);

/// The reference options the study asks for (refSpp, refSampler, refBatch, threads, progress).
ReferenceOptions referenceOptions(const StudyConfig& config);

/// The CSV path the config writes.
std::string csvPath(const StudyConfig& config);

}  // namespace aliaslab
