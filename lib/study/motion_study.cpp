// The motion study (study/motion_study.h): references per frame, K seeds x F frames per configuration.
#include "study/motion_study.h"

#include <cmath>
#include <cstdio>
#include <ostream>

#include "core/error.h"
#include "core/format.h"
#include "filter/filter.h"
#include "measure/metrics.h"
#include "render/sample_source.h"
#include "study/study_scene.h"

namespace aliaslab {
namespace {

const FilterSpec kArea{"box", 0.5};

std::string number(double v) { return formatNumber(v, "%.9g"); }

}  // namespace

void setMotionFrame(StudyScene& s, const Camera& base, uint64_t baseHash, int t, double dx, double dy) {
  const Vec2 offset = frameScreenOffset(t, dx, dy, s.width, s.height);
  s.scene.camera = makeShiftedCamera(base, offset);
  char exact[96];  // %a: every bit of the offset, so no two offsets share a key
  std::snprintf(exact, sizeof exact, "motion offset %a %a", double(offset.x()), double(offset.y()));
  s.contentHash = offset.isZero(0.f) ? baseHash : hashBytes(exact, baseHash);
}

std::pair<double, double> parseMotion(const std::string& text) {
  const size_t comma = text.find(',');
  double v[2] = {NAN, NAN};
  if (comma != std::string::npos && text.find(',', comma + 1) == std::string::npos) {
    const std::string parts[2] = {text.substr(0, comma), text.substr(comma + 1)};
    for (int i = 0; i < 2; ++i) try {
        size_t used = 0;
        v[i] = std::stod(parts[i], &used);
        if (used != parts[i].size() || parts[i].empty()) v[i] = NAN;
      } catch (const std::exception&) {
      }
  }
  if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || std::abs(v[0]) > 1e4 || std::abs(v[1]) > 1e4)
    throw OptionError("motion", "expected dx,dy: two finite numbers of pixels per frame (at most 1e4), e.g. "
                                "0.25,0; found '" + text + "'");
  return {v[0], v[1]};
}

FilterSpec parseFilterSpec(const std::string& text) {
  const size_t colon = text.find(':');
  if (colon == std::string::npos || colon == 0)
    throw OptionError("filter", "expected name:radius (e.g. gaussian:1.5), found '" + text + "'");
  const std::string name = text.substr(0, colon), r = text.substr(colon + 1);
  double radius = NAN;
  try {
    size_t used = 0;
    radius = std::stod(r, &used);
    if (used != r.size()) radius = NAN;
  } catch (const std::exception&) {
  }
  if (!std::isfinite(radius) || radius <= 0 || radius > 64)
    throw OptionError("filter", "'" + text + "': the radius must be a number in (0, 64]");
  makeFilter(name, static_cast<float>(radius));  // throws OptionError("filter") naming the valid names
  return {name, radius};
}

void validateMotionStudy(const MotionStudyConfig& c) {
  if (c.frames < 2 || c.frames > 1000) throw OptionError("frames", "must be in 2..1000, found " + std::to_string(c.frames));
  if (!std::isfinite(c.dx) || !std::isfinite(c.dy) || std::abs(c.dx) > 1e4 || std::abs(c.dy) > 1e4)
    throw OptionError("motion", "dx and dy must be finite numbers of pixels per frame (at most 1e4)");
  if (c.seeds < 2 || c.seeds > 4096) throw OptionError("seeds", "must be in 2..4096, found " + std::to_string(c.seeds));
  if (c.size < 0 || c.size > 16384) throw OptionError("size", "must be in 1..16384 (0: the scene's render line)");
  if (c.samplers.empty() || c.spp.empty() || c.filters.empty())
    throw OptionError("sampler", "the lists of samplers, spp and filters must not be empty");
  for (int n : c.spp)
    for (const std::string& s : c.samplers) makeSampleSource(s, n, 0);  // throws OptionError("sampler"/"spp")
  for (const FilterSpec& f : c.filters) makeFilter(f.first, static_cast<float>(f.second));
  validateReferenceOptions(c.reference);
  checkStudyScene(c.scene, 0, 0, 0, c.size);
}

std::vector<MotionRow> runMotionStudy(const MotionStudyConfig& c, std::ostream& log) {
  validateMotionStudy(c);
  std::unique_ptr<StudyScene> s = loadStudyScene(c.scene, 0, 0, 0, c.size);
  const std::unique_ptr<Camera> base = std::move(s->scene.camera);
  const uint64_t baseHash = s->contentHash;
  const int F = c.frames, K = c.seeds, W = s->width, H = s->height;

  // References per frame: the filters, then the area target.
  std::vector<FilterSpec> specs = c.filters;
  specs.push_back(kArea);
  std::vector<ReferenceSet> refs;
  for (int t = 0; t < F; ++t) {
    setMotionFrame(*s, *base, baseHash, t, c.dx, c.dy);
    if (c.progress) log << "motion: references of frame " << t + 1 << "/" << F << "\n" << std::flush;
    ReferenceOptions o = c.reference;
    o.progress = o.progress && c.progress;
    refs.push_back(c.cache.empty() ? renderReferences(*s, specs, o) : cachedReferences(*s, specs, o, c.cache));
  }
  const size_t area = specs.size() - 1;
  std::vector<RefEstimate> targets;
  for (const ReferenceSet& r : refs)
    targets.push_back({&r.images[area].image, &r.images[area].halfDiff, kArea.second});

  std::vector<std::unique_ptr<Filter>> filters;
  for (const FilterSpec& f : c.filters) filters.push_back(makeFilter(f.first, static_cast<float>(f.second)));
  std::vector<MotionRow> rows;
  for (const std::string& sampler : c.samplers)
    for (int spp : c.spp) {
      // images[j][k][t]: filter j, seed k, frame t
      std::vector<std::vector<std::vector<Image>>> images(filters.size(),
                                                          std::vector<std::vector<Image>>(K, std::vector<Image>(F)));
      for (int k = 0; k < K; ++k) {
        const auto source = makeSampleSource(sampler, spp, static_cast<uint64_t>(k));
        for (int t = 0; t < F; ++t) {
          setMotionFrame(*s, *base, baseHash, t, c.dx, c.dy);
          const SampleBuffer samples = source->trace(*s->tracer, W, H, c.threads);
          for (size_t j = 0; j < filters.size(); ++j)
            images[j][k][t] = reconstruct(samples, *filters[j], ReconMode::WeightedAverage, c.threads).image;
        }
        if (c.progress) log << "motion: " << sampler << " " << spp << " spp: seed " << k + 1 << "/" << K << "\n" << std::flush;
      }
      for (size_t j = 0; j < filters.size(); ++j) {
        MotionRow row;
        row.scene = s->stem, row.sampler = sampler, row.spp = spp;
        row.filter = c.filters[j].first, row.radius = c.filters[j].second;
        row.dx = c.dx, row.dy = c.dy;
        row.motion = computeMotionMetrics(images[j], targets);
        std::vector<RefEstimate> own;
        for (int t = 0; t < F; ++t) own.push_back({&refs[t].images[j].image, &refs[t].images[j].halfDiff, row.radius});
        row.motionFilter = computeMotionMetrics(images[j], own);
        for (int t = 0; t < F; ++t) {
          std::vector<Image> frame;
          for (int k = 0; k < K; ++k) frame.push_back(images[j][k][t]);
          const ReferenceImage& g = refs[t].images[j];
          const Metrics m = computeMetrics(frame, {&g.image, &g.halfDiff, c.filters[j].second}, {targets[t]});
          row.blur += m.targets[0].blur / F, row.noise += m.noise / F;
          if (t == 0) row.mseTarget = m.targets[0].mseTarget, row.mseTargetSe = m.targets[0].mseTargetSe;
        }
        rows.push_back(row);
      }
    }
  s->scene.camera.reset();
  return rows;
}

std::string motionCsv(const std::vector<MotionRow>& rows) {
  std::string out =
      "scene,sampler,spp,filter,radius,frames,motion_dx,motion_dy,seeds,shimmer,shimmer_se,flicker_same_seed,"
      "flicker_same_seed_se,flicker_new_seed,flicker_new_seed_se,shimmer_filter,shimmer_filter_se,blur,noise,mse_target,mse_target_se\n";
  for (const MotionRow& r : rows) {
    const MotionMetrics& m = r.motion;
    out += r.scene + "," + r.sampler + "," + std::to_string(r.spp) + "," + r.filter + "," + number(r.radius) + "," +
           std::to_string(m.frames) + "," + number(r.dx) + "," + number(r.dy) + "," + std::to_string(m.seeds);
    for (double v : {m.shimmer, m.shimmerSe, m.flickerSameSeed, m.flickerSameSeedSe, m.flickerNewSeed,
                     m.flickerNewSeedSe, r.motionFilter.shimmer, r.motionFilter.shimmerSe, r.blur, r.noise, r.mseTarget, r.mseTargetSe})
      out += "," + number(v);
    out += "\n";
  }
  return out;
}

}  // namespace aliaslab
