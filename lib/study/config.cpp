#include "study/config.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>

#include "core/error.h"
#include "core/files.h"
#include "core/format.h"
#include "filter/filter.h"
#include "render/adaptive.h"
#include "sampling/sampler.h"
#include "study/csv.h"
#include "study/study_scene.h"
#include "study/sweep_memory.h"

namespace aliaslab {

namespace fs = std::filesystem;

namespace {
std::vector<std::string> expandSceneList(const std::vector<std::string>& scenes);
std::string formatValue(const std::string& s) { return "'" + s + "'"; }
std::string formatValue(int v) { return std::to_string(v); }
std::string formatValue(double v) { return formatNumber(v); }
}

std::vector<std::string> expandScenePaths(const std::vector<std::string>& scenes) {
  std::vector<std::string> out = expandSceneList(scenes);
  // Rows are keyed by the scene's file stem: two different files with one stem would share rows.
  std::vector<std::string> unique;
  std::map<std::string, std::string> byStem;
  for (const std::string& s : out) {
    const std::string stem = fs::path(s).stem().string();
    const auto [it, fresh] = byStem.emplace(stem, s);
    if (fresh) unique.push_back(s);
    else if (!sameFile(it->second, s))
      throw OptionError("--scenes", "two scenes have the same name '" + stem + "' ('" + it->second + "' and '" + s +
                                        "'); the CSV keys rows by scene name, so rename one of them");
  }
  return unique;
}

namespace {
std::vector<std::string> expandSceneList(const std::vector<std::string>& scenes) {
  std::vector<std::string> out;
  for (const std::string& s : scenes) {
    std::error_code ec;
    if (fs::is_directory(s, ec)) {
      std::vector<std::string> found;
      for (const auto& e : fs::directory_iterator(s, ec))
        if (e.path().extension() == ".txt") found.push_back(e.path().string());
      std::sort(found.begin(), found.end());
      if (found.empty()) throw FileError(s, "folder holds no *.txt scene");
      out.insert(out.end(), found.begin(), found.end());
    } else {
      out.push_back(s);
    }
  }
  return out;
}
}  // namespace

std::vector<FilterSpec> studyFilters(const StudyConfig& config) {
  std::vector<FilterSpec> out;
  for (const std::string& f : config.filters) {
    std::vector<double> radii = config.radii;
    if (f == "box" && config.classicBox && std::find(radii.begin(), radii.end(), 0.5) == radii.end())
      radii.insert(radii.begin(), 0.5);
    for (double r : radii) out.emplace_back(f, r);
  }
  return out;
}

namespace {
// Each (filter, radius) made once (makeFilter) and shared by every configuration that uses it.
class FilterCache {
 public:
  StudyFilter get(const FilterSpec& spec) {
    auto& f = built_[spec];
    if (!f) f = makeFilter(spec.first, static_cast<float>(spec.second));
    return {spec, f};
  }

 private:
  std::map<FilterSpec, std::shared_ptr<const Filter>> built_;
};
}  // namespace

std::vector<SampleSetGroup> expandStudy(const StudyConfig& config, std::vector<std::string>* notes) {
  std::vector<SampleSetGroup> groups;
  FilterCache cache;
  std::vector<StudyFilter> filters;
  for (const FilterSpec& spec : studyFilters(config)) filters.push_back(cache.get(spec));
  std::set<std::string> noted;
  auto note = [&](const std::string& text) {
    if (notes && noted.insert(text).second) notes->push_back(text);
  };
  for (const std::string& scene : expandScenePaths(config.scenes))
    for (const std::string& sampler : config.samplers)
      for (int spp : config.spp)
      for (const std::string& prefilter : config.prefilter) {
        SampleSetGroup g;
        g.index = static_cast<int>(groups.size());
        g.scene = scene, g.sampler = sampler, g.spp = spp, g.prefilter = prefilter;
        for (const std::string& modeName : config.reconstruction) {
          const ReconMode mode = parseReconMode(modeName);
          if (mode == ReconMode::Supersample) {
            const int k = static_cast<int>(std::lround(std::sqrt(spp)));
            if (sampler == "uniform" && k * k == spp) g.configs.push_back({cache.get({"box", 0.5}), mode});
            else note("supersample: only the uniform sampler at square spp; skipped " + sampler + " spp " +
                      std::to_string(spp));
            continue;
          }
          if (mode == ReconMode::ImportanceSampled && isAdaptiveSamplerName(sampler)) {
            note("importance: adaptive samplers place their own samples (no filter importance); skipped " + sampler);
            continue;
          }
          for (const StudyFilter& f : filters) g.configs.push_back({f, mode});
        }
        groups.push_back(std::move(g));
      }
  return groups;
}

bool parsePrefilter(const std::string& name, const std::string& option) {
  if (name == "none") return false;
  if (name == "footprint") return true;
  throw OptionError(option, "unknown pre-filtering '" + name + "' (valid: none, footprint)");
}

std::vector<SampleSetGroup> shardGroups(const std::vector<SampleSetGroup>& groups, int index, int count) {
  std::vector<SampleSetGroup> out;
  for (const SampleSetGroup& g : groups)
    if (g.index % count == index) out.push_back(g);
  return out;
}

Target parseTarget(const std::string& text) {
  if (text == "area") return {{"box", 0.5}, "box:" + formatNumber(0.5)};
  const size_t colon = text.find(':');
  const std::string usage = "expected 'area' or filter:radius (e.g. gaussian:1.5, lanczos:2), found '" + text + "'";
  if (colon == std::string::npos || colon == 0) throw OptionError("--target", usage);
  const std::string name = text.substr(0, colon), radius = text.substr(colon + 1);
  double r = 0;
  try {
    size_t used = 0;
    r = std::stod(radius, &used);
    if (used != radius.size()) throw std::invalid_argument("x");
  } catch (const std::exception&) {
    throw OptionError("--target", usage);
  }
  if (!(std::isfinite(r) && r > 0)) throw OptionError("--target", "the radius must be finite and > 0, found '" + text + "'");
  relabelOption("--filter", "--target", [&] {
    relabelOption("--radius", "--target", [&] { makeFilter(name, static_cast<float>(r)); });
  });
  return {{name, r}, name + ":" + formatNumber(r)};
}

void parseShard(const std::string& text, int& index, int& count) {
  const size_t slash = text.find('/');
  try {
    if (slash == std::string::npos) throw std::invalid_argument("x");
    size_t a = 0, b = 0;
    index = std::stoi(text.substr(0, slash), &a);
    count = std::stoi(text.substr(slash + 1), &b);
    if (a != slash || b != text.size() - slash - 1) throw std::invalid_argument("x");
  } catch (const std::exception&) {
    throw OptionError("--shard", "expected i/N (e.g. 0/4), found '" + text + "'");
  }
  if (count < 1 || index < 0 || index >= count)
    throw OptionError("--shard", "need 0 <= i < N (shards are numbered 0 to N-1), found '" + text + "'");
}

void checkShardSet(const std::vector<std::string>& inputs) {
  static const std::regex name(R"(shard-(\d+)-of-(\d+)\.csv$)");
  std::map<int, std::vector<int>> seen;  // N -> the i given
  for (const std::string& in : inputs) {
    std::smatch m;
    const std::string file = fs::path(in).filename().string();
    if (!std::regex_search(file, m, name)) continue;
    try {
      seen[std::stoi(m[2].str())].push_back(std::stoi(m[1].str()));
    } catch (const std::exception&) {
      throw OptionError("--merge", "shard number out of range in '" + in + "'");
    }
  }
  if (seen.size() > 1)
    throw OptionError("--merge", "the inputs are shards of different splits (" + std::to_string(seen.begin()->first) +
                                     " and " + std::to_string(seen.rbegin()->first) + " shards)");
  for (auto& [count, given] : seen) {
    std::sort(given.begin(), given.end());
    for (int i = 0; i < count; ++i)
      if (!std::binary_search(given.begin(), given.end(), i))
        throw OptionError("--merge", "shard " + std::to_string(i) + " of " + std::to_string(count) +
                                         " is missing (study.shard-" + std::to_string(i) + "-of-" +
                                         std::to_string(count) + ".csv); the merge would lack its rows");
    if (given.back() >= count || std::adjacent_find(given.begin(), given.end()) != given.end())
      throw OptionError("--merge", "shard files of " + std::to_string(count) +
                                       " shards given twice or numbered beyond N-1");
  }
}

std::string csvPath(const StudyConfig& config) {
  if (!config.csv.empty()) return config.csv;
  if (config.shardCount > 1)
    return (fs::path(config.out) / ("study.shard-" + std::to_string(config.shardIndex) + "-of-" +
                                    std::to_string(config.shardCount) + ".csv"))
        .string();
  return (fs::path(config.out) / "study.csv").string();
}

namespace {
// The folders a validation created (deepest last), removed again when a later check fails.
class NewFolders {
 public:
  ~NewFolders() {
    if (keep_) return;
    std::error_code ec;
    for (auto it = made_.rbegin(); it != made_.rend(); ++it) fs::remove(*it, ec);  // only if still empty
  }
  /// `dir` exists and is writable afterwards, or OptionError(option); remembers what it had to create.
  void require(const std::string& dir, const std::string& option) {
    std::vector<fs::path> missing;
    std::error_code ec;
    for (fs::path p = fs::absolute(dir, ec).lexically_normal(); !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
      missing.push_back(p);
      if (p == p.parent_path()) break;
    }
    fs::create_directories(dir, ec);
    for (auto it = missing.rbegin(); it != missing.rend(); ++it)
      if (fs::is_directory(*it, ec)) made_.push_back(*it);
    if (!fs::is_directory(dir, ec)) throw OptionError(option, "cannot create folder '" + dir + "'");
    if (::access(dir.c_str(), W_OK) != 0) throw OptionError(option, "folder '" + dir + "' is not writable");
  }
  /// Every check passed: keep the folders.
  void keep() { keep_ = true; }

 private:
  std::vector<fs::path> made_;
  bool keep_ = false;
};
}  // namespace

ReferenceOptions referenceOptions(const StudyConfig& c) {
  ReferenceOptions o;
  o.spp = c.refSpp, o.sampler = c.refSampler, o.batchSpp = c.refBatch, o.threads = c.threads;
  o.progress = c.progress;
  return o;
}

StudyPlan validateStudy(const StudyConfig& c) {
  StudyPlan plan;
  // Lists and numbers.
  if (c.samplers.empty()) throw OptionError("--samplers", "needs at least one sampler");
  if (c.filters.empty()) throw OptionError("--filters", "needs at least one filter");
  if (c.spp.empty()) throw OptionError("--spp", "needs at least one sample count");
  if (c.radii.empty()) throw OptionError("--radii", "needs at least one radius");
  if (c.reconstruction.empty()) throw OptionError("--reconstruction", "needs at least one mode");
  if (c.prefilter.empty()) throw OptionError("--prefilter", "needs at least one of none, footprint");
  for (const std::string& p : c.prefilter) parsePrefilter(p);
  for (size_t i = 0; i < c.prefilter.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (c.prefilter[i] == c.prefilter[j]) throw OptionError("--prefilter", "'" + c.prefilter[i] + "' given twice");
  if (c.scenes.empty()) throw OptionError("--scenes", "needs at least one scene file or folder");
  if (c.seeds < 2) throw OptionError("--seeds", "needs K >= 2 (noise is a variance over seeds), found " +
                                                    std::to_string(c.seeds));
  // The reference options: one check (study/reference.h), the same as the reference front end's.
  relabelOption("--sampler", "--ref-sampler", [&] { validateReferenceOptions(referenceOptions(c)); });
  if (c.threads < 0) throw OptionError("--threads", "must be >= 0");
  if ((c.width > 0) != (c.height > 0) || c.width < 0 || c.height < 0)
    throw OptionError("--size", "expected two positive numbers W H");
  if (c.maxSize < 0) throw OptionError("--max-size", "must be >= 0");
  if (c.longSide < 0) throw OptionError("--long-side", "must be >= 0");
  plan.target = parseTarget(c.target);
  // A name or number listed twice would make every configuration of it twice (the CSV keeps one).
  auto once = [](const auto& list, const char* option) {
    for (size_t i = 0; i < list.size(); ++i)
      for (size_t j = i + 1; j < list.size(); ++j)
        if (list[i] == list[j]) throw OptionError(option, "lists " + formatValue(list[i]) + " twice");
  };
  once(c.samplers, "--samplers"), once(c.spp, "--spp"), once(c.filters, "--filters"), once(c.radii, "--radii");
  once(c.reconstruction, "--reconstruction");
  for (int spp : c.spp)
    if (spp < 1) throw OptionError("--spp", "sample counts must be >= 1, found " + std::to_string(spp));
  for (double r : c.radii)
    if (!(std::isfinite(r) && r > 0)) throw OptionError("--radii", "radii must be finite and > 0, found " +
                                                                      formatNumber(r));
  // Names: the factories' own messages list the valid ones.
  for (const std::string& m : c.reconstruction) parseReconMode(m);
  for (const std::string& s : c.samplers)
    for (int spp : c.spp)
      relabelOption("--sampler", "--samplers", [&] {
        if (isAdaptiveSamplerName(s)) makeAdaptiveSampler(s, spp, 0);
        else makeSampler(s, spp, 0);
      });
  // The groups, every (filter, radius) built here once (the factory names the valid filters).
  relabelOption("--filter", "--filters", [&] {
    relabelOption("--radius", "--radii", [&] { plan.groups = expandStudy(c, &plan.notes); });
  });

  // Scenes: present and parseable, with a known size; never the CSV this run writes.
  // Memory is per group (the sweep holds one group's seeds in flight, study/sweep_memory.h sweepMemoryBound),
  // plus the scene's reference images and the reference pass's sums: the largest group decides.
  size_t rowsPerGroup = 0, weightedRows = 0;
  for (const SampleSetGroup& g : plan.groups) {
    rowsPerGroup = std::max(rowsPerGroup, g.configs.size());
    weightedRows = std::max<size_t>(weightedRows, std::count_if(g.configs.begin(), g.configs.end(), [](const Configuration& x) {
                                      return x.mode == ReconMode::WeightedAverage;
                                    }));
  }
  const double references = double(studyFilters(c).size() + 2) * (3 * sizeof(float) + 4 * sizeof(double));
  for (const std::string& path : expandScenePaths(c.scenes)) {
    if (!fs::is_regular_file(path)) throw FileError(path, "scene file not found");
    refuseOutputOverInput("--csv", csvPath(c), {path});
    const SceneSize size = plan.sceneSizes[path] = checkStudyScene(path, c.width, c.height, c.maxSize, c.longSide);
    // Memory, before any allocation: the scheduler's bound for the largest group at the largest spp, plus
    // the references (an image and a pass's 4 sums per (filter, radius), the area and the target).
    const int maxSpp = *std::max_element(c.spp.begin(), c.spp.end());
    const double pixels = double(size.width) * size.height;
    requireMemory(double(sweepMemoryBound(c.threads, size.width, size.height, maxSpp, rowsPerGroup, weightedRows,
                                          c.seeds)) +
                      pixels * references,
                  "--size",
                  fs::path(path).stem().string() + " at " + std::to_string(size.width) + " x " +
                      std::to_string(size.height) + " and " + std::to_string(maxSpp) + " spp");
  }

  // Output folders: all or none (a failed check removes the folders made before it).
  requireOutputFolders({{c.out, "--out"}, {fs::path(csvPath(c)).parent_path().string(), "--csv"}, {c.cache, "--cache"}});
  return plan;
}

void requireOutputFolders(const std::vector<std::pair<std::string, std::string>>& folders) {
  NewFolders made;
  for (const auto& [dir, option] : folders) made.require(dir.empty() ? "." : dir, option);
  made.keep();
}

}  // namespace aliaslab

namespace aliaslab {

namespace {
// The value of column `name` in a parsed row.
const std::string& field(const std::vector<std::string>& f, const std::string& name) {
  const auto& cols = csvColumns();
  return f[static_cast<size_t>(std::find(cols.begin(), cols.end(), name) - cols.begin())];
}
std::string sameStudyAdvice() {
  return ". A study CSV holds one study: rerun with the options it was made with to resume it, or give another "
         "--out or --csv for the new study";
}
}  // namespace

void checkSameStudy(const std::string& csv, const std::vector<std::string>& lines, const StudyConfig& c) {
  const std::pair<const char*, const char*> studyWide[] = {{"seeds", "--seeds"}, {"ref_spp", "--ref-spp"}};
  const std::string wanted[] = {std::to_string(c.seeds), std::to_string(c.refSpp)};
  for (size_t i = 0; i < lines.size(); ++i) {
    const auto f = splitCsvLine(lines[i]);
    if (f.size() != csvColumns().size()) continue;
    for (size_t k = 0; k < std::size(studyWide); ++k)
      if (field(f, studyWide[k].first) != wanted[k])
        throw OptionError(studyWide[k].second, csv + " holds a study made with " + studyWide[k].first + " " +
                                                   field(f, studyWide[k].first) + " (data row " +
                                                   std::to_string(i + 1) + "); this run asks for " + wanted[k] +
                                                   sameStudyAdvice());
  }
}

void checkSameSceneSize(const std::string& csv, const std::vector<std::string>& lines, const std::string& stem,
                        int width, int height) {
  for (size_t i = 0; i < lines.size(); ++i) {
    const auto f = splitCsvLine(lines[i]);
    if (f.size() != csvColumns().size() || field(f, "scene") != stem) continue;
    if (field(f, "width") != std::to_string(width) || field(f, "height") != std::to_string(height))
      throw OptionError("--size", csv + " holds scene " + stem + " at " + field(f, "width") + " x " +
                                      field(f, "height") + " (data row " + std::to_string(i + 1) +
                                      "); this run renders it at " + std::to_string(width) + " x " +
                                      std::to_string(height) + " (--size / --max-size)" + sameStudyAdvice());
  }
}

}  // namespace aliaslab
