#include "study/config.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "core/error.h"
#include "core/files.h"
#include "core/format.h"
#include "filter/filter.h"
#include "render/sample_source.h"
#include "study/study_scene.h"

namespace aliaslab {

namespace fs = std::filesystem;

namespace {
std::vector<std::string> expandSceneList(const std::vector<std::string>& scenes);
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
      throw OptionError("scenes", "two scenes have the same name '" + stem + "' ('" + it->second + "' and '" + s +
                                        "'); the CSV keys rows by scene name, so rename one of them");
  }
  return unique;
}

namespace {
std::vector<std::string> expandSceneList(const std::vector<std::string>& scenes) {
  std::vector<std::string> out;
  for (const std::string& s : scenes) {
    std::error_code ec;
    if (s.empty()) throw OptionError("scenes", "an empty name in the list: give scene files or folders");
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
    auto absent = [&](double r) { return std::find(radii.begin(), radii.end(), r) == radii.end(); };
    if (f == "box" && config.classicBox && absent(0.5)) radii.insert(radii.begin(), 0.5);
    if (config.naturalRadii && absent(defaultFilterRadius(f))) radii.push_back(defaultFilterRadius(f));
    for (double r : radii) out.emplace_back(f, r);
  }
  return out;
}

void setStudyRadii(StudyConfig& config, const std::vector<std::string>& tokens) {
  std::vector<double> radii;
  bool natural = false;
  for (const std::string& t : tokens) {
    if (t == "natural") {
      if (natural) throw OptionError("radii", "lists 'natural' twice");
      natural = true;
      continue;
    }
    const double r = parseFiniteNumber(t);
    if (!(r > 0))
      throw OptionError("radii", "expected radii in pixels (finite numbers > 0) or 'natural' (every filter also at "
                                 "its own natural radius), found '" + t + "'");
    radii.push_back(r);
  }
  if (radii.empty() && !natural) throw OptionError("radii", "needs at least one radius or 'natural'");
  config.radii = radii, config.naturalRadii = natural;
}

std::vector<std::string> studyRadiusTokens(const StudyConfig& config) {
  std::vector<std::string> out;
  for (double r : config.radii) out.push_back(formatReal(r));
  if (config.naturalRadii) out.push_back("natural");
  return out;
}

std::vector<SampleSetGroup> expandStudy(const StudyConfig& config, FilterCache& cache,
                                        std::vector<std::string>* notes) {
  std::vector<SampleSetGroup> groups;
  const std::vector<StudyFilter> filters = cache.get(studyFilters(config));
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
            if (sampler == "uniform" && k * k == spp) g.configs.push_back({cache.get(kAreaSpec), mode});
            else note("supersample: only the uniform sampler at square spp; skipped " + sampler + " spp " +
                      std::to_string(spp));
            continue;
          }
          if (mode == ReconMode::ImportanceSampled && makeSampleSource(sampler, spp, 0)->adaptive()) {
            note("importance: adaptive samplers place their own samples (no filter importance); skipped " + sampler);
            continue;
          }
          for (const StudyFilter& f : filters) g.configs.push_back({f, mode});
        }
        groups.push_back(std::move(g));
      }
  return groups;
}

bool parsePrefilter(const std::string& name, const std::string& key) {
  if (name == "none") return false;
  if (name == "footprint") return true;
  throw OptionError(key, "unknown pre-filtering '" + name + "' (valid: none, footprint)");
}

std::vector<SampleSetGroup> shardGroups(const std::vector<SampleSetGroup>& groups, int index, int count) {
  std::vector<SampleSetGroup> out;
  for (const SampleSetGroup& g : groups)
    if (g.index % count == index) out.push_back(g);
  return out;
}

Target parseTarget(const std::string& text, FilterCache& filters) {
  if (text == "area") return {filters.get(kAreaSpec), "box:" + formatNumber(0.5)};
  const size_t colon = text.find(':');
  const std::string usage = "expected 'area' or filter:radius (e.g. gaussian:1.5, lanczos:2), found '" + text + "'";
  if (colon == std::string::npos || colon == 0) throw OptionError("target", usage);
  const std::string name = text.substr(0, colon), radius = text.substr(colon + 1);
  double r = 0;
  try {
    size_t used = 0;
    r = std::stod(radius, &used);
    if (used != radius.size()) throw std::invalid_argument("x");
  } catch (const std::exception&) {
    throw OptionError("target", usage);
  }
  if (!(std::isfinite(r) && r > 0)) throw OptionError("target", "the radius must be finite and > 0, found '" + text + "'");
  StudyFilter filter;
  rekeyOption("filter", "target", [&] { rekeyOption("radius", "target", [&] { filter = filters.get({name, r}); }); });
  return {filter, name + ":" + formatNumber(r)};
}

std::vector<Target> parseTargets(const std::vector<std::string>& texts, FilterCache& filters) {
  if (texts.empty()) throw OptionError("target", "needs at least one target (e.g. area)");
  std::vector<Target> out;
  for (const std::string& t : texts) {
    Target parsed = parseTarget(t, filters);
    for (const Target& seen : out) {
      const bool same = seen.filter.spec == parsed.filter.spec;
      if (same || seen.label == parsed.label)  // the label is the CSV's key: one row each
        throw OptionError("target", "lists the target " + parsed.label + " twice ('" + t + "' and '" + seen.label +
                                        "'" + (same ? ")" : ": the CSV labels both alike)"));
    }
    out.push_back(std::move(parsed));
  }
  return out;
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
    throw OptionError("shard", "expected i/N (e.g. 0/4), found '" + text + "'");
  }
  if (count < 1 || index < 0 || index >= count)
    throw OptionError("shard", "need 0 <= i < N (shards are numbered 0 to N-1), found '" + text + "'");
}

std::string csvPath(const StudyConfig& config) {
  if (!config.csv.empty()) return config.csv;
  if (config.shardCount > 1)
    return (fs::path(config.out) / ("study.shard-" + std::to_string(config.shardIndex) + "-of-" +
                                    std::to_string(config.shardCount) + ".csv"))
        .string();
  // OUT/study.csv, or OUT/study.csv.gz when only that exists (a study kept gzipped is resumed under its name)
  const std::string plain = (fs::path(config.out) / "study.csv").string();
  std::error_code ec;
  return !fs::exists(plain, ec) && fs::exists(plain + ".gz", ec) ? plain + ".gz" : plain;
}

ReferenceOptions referenceOptions(const StudyConfig& c) {
  ReferenceOptions o;
  o.spp = c.refSpp, o.sampler = c.refSampler, o.batchSpp = c.refBatch, o.threads = c.threads;
  o.progress = c.progress;
  return o;
}

}  // namespace aliaslab
