// The fixed grid's alignment (study/sweep/alignment.h) through the whole sweep: its columns equal the grid rendered
// directly at the same camera offsets, through another path (the scene file with its orthographic camera moved by
// the offset, rendered by the library's reconstruct, not the sweep's shared splat), against the targets' references
// rendered for that moved camera, the mse computed here; the rows of other samplers have empty alignment columns;
// every other column is that of the same study without alignment; no number depends on the thread count, shards
// merge into the whole, a resumed run refills lost rows with the same numbers, and a CSV made with another K is
// not resumed. Also the natural radius: the token, the column, each (filter, radius) once.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/error.h"
#include "film/film.h"
#include "filter/filter.h"
#include "render/sample_source.h"
#include "study/sweep/alignment.h"
#include "study/config.h"
#include "study/records/csv.h"
#include "study/records/merge.h"
#include "study/study_scene.h"
#include "study/sweep/sweep.h"
#include "support/scratch_dir.h"
#include "support/study_rows.h"

namespace aliaslab {
namespace {
namespace fs = std::filesystem;

const fs::path& scratch() { return testing::scratchDir("aliaslab_sweep_alignment"); }

constexpr int kSize = 24;  // pixels a side; the camera's square screen spans 2 world units

// Vertical stripes at 24 cycles per unit = 2 cycles per pixel, the 2 x 2 grid's own rate: its two columns of points
// (x = 1/4, 3/4 in the pixel) see the same phase, so the 4-spp grid's image is 0.5 - 0.5 cos(4 pi o_x) for a film
// offset o_x, all its error a matter of alignment (the 4 x 4 grid at 16 spp averages the stripes out). The
// orthographic camera's centre sits at (cx, cy).
std::string gratingScene(const std::string& name, double cx, double cy) {
  const fs::path p = scratch() / (name + ".txt");
  char camera[160];
  std::snprintf(camera, sizeof camera, "OrthographicCamera { center %.9g %.9g 1 direction 0 0 -1 up 0 1 0 size 2 }\n",
                cx, cy);
  std::ofstream(p) << "# render: -size " << kSize << " " << kSize << "\n" << camera
                   << "Background { color 1 0 0 }\n"
                      "Materials { numMaterials 3 PhongMaterial { diffuseColor 0 0 0 } "
                      "PhongMaterial { diffuseColor 1 1 1 }\n"
                      "Pattern { materialIndex 0 materialIndex 1 type grating frequency 24 angle 0 } }\n"
                      "Group { numObjects 1 MaterialIndex 2 Plane { normal 0 0 1 offset 0 } }\n";
  return p.string();
}

StudyConfig study(const std::string& name, int offsets, int threads) {
  StudyConfig c;
  c.scenes = {gratingScene("grating", 0, 0)};
  c.samplers = {"uniform", "jittered"};
  c.spp = {4, 16};
  c.filters = {"box", "gaussian"};
  c.radii = {1.0};
  c.naturalRadii = true;  // box 0.5, gaussian 1.5
  c.reconstruction = {"weighted", "supersample"};
  c.targets = {"area", "gaussian:1.5"};
  c.seeds = 3, c.refSpp = 64;
  c.alignOffsets = offsets, c.alignRefSpp = 32;
  c.out = (scratch() / name).string();
  c.cache = (scratch() / "cache").string();  // shared: the entries are keyed by content, offset included
  c.threads = threads;
  c.images = false;
  c.progress = false;
  return c;
}

std::vector<std::vector<std::string>> readRows(const std::string& csv) { return aliaslab::testing::readStudyRows(csv); }

std::vector<std::vector<std::string>> sweep(const StudyConfig& c) {
  runSweep(c);
  return readRows(csvPath(c));
}

const std::string& at(const std::vector<std::string>& f, const std::string& name) { return f[csvColumn(name)]; }

bool variable(size_t i) {  // columns that may differ between runs
  for (size_t t : csvTimingColumns())
    if (t == i) return true;
  return i == csvColumn("threads");
}

bool alignmentColumn(size_t i) { return csvColumns()[i].rfind("align_", 0) == 0; }

// The mse of `image` against the reference `t` with its variance (mean D^2) subtracted, computed here; `raw` gets
// the mean square before the subtraction (the scale of the two paths' rounding difference).
double mseAgainst(const Image& image, const ReferenceImage& t, double& raw) {
  double sse = 0, var = 0;
  const size_t n = size_t(image.width()) * image.height() * 3;
  for (size_t i = 0; i < n; ++i) {
    const double e = double(image.data()[i]) - t.image.data()[i];
    sse += e * e, var += double(t.halfDiff.data()[i]) * t.halfDiff.data()[i];
  }
  raw = sse / double(n);
  return (sse - var) / double(n);
}

TEST(SweepAlignment, ColumnsEqualTheGridRenderedAtEachOffset) {
  const StudyConfig c = study("aligned", 4, 2);
  const auto rows = sweep(c);
  FilterCache filters;
  const std::vector<StudyFilter> targets = filters.get({{"box", 0.5}, {"gaussian", 1.5}});
  ReferenceOptions o = referenceOptions(c);
  o.spp = c.alignRefSpp, o.progress = false;
  // Per offset k: the scene with its camera moved by the film offset (film position p then sees what p + o saw;
  // the camera's screen spans 2 units over kSize pixels), the grid traced once and the targets' references.
  struct Offset {
    std::unique_ptr<StudyScene> scene;
    ReferenceSet refs;
    std::map<int, SampleBuffer> grid;  // by spp
  };
  std::vector<Offset> offsets;
  for (int k = 0; k < c.alignOffsets; ++k) {
    const Vec2 o2 = alignmentOffset(k);
    EXPECT_TRUE(o2.x() >= -0.5f && o2.x() < 0.5f && o2.y() >= -0.5f && o2.y() < 0.5f) << k;
    const double unit = 2.0 / kSize;
    Offset off;
    off.scene = loadStudyScene(gratingScene("moved" + std::to_string(k), o2.x() * unit, o2.y() * unit));
    off.refs = renderReferences(*off.scene, targets, o);
    for (int spp : c.spp) off.grid[spp] = makeSampleSource("uniform", spp, 0)->trace(*off.scene->tracer, kSize, kSize, 1);
    offsets.push_back(std::move(off));
  }
  size_t checked = 0, empty = 0;
  for (const auto& f : rows) {
    if (at(f, "sampler") != "uniform") {
      for (size_t i = 0; i < f.size(); ++i)
        if (alignmentColumn(i)) EXPECT_EQ(f[i], "") << csvColumns()[i];
      ++empty;
      continue;
    }
    const int spp = std::stoi(at(f, "spp"));
    const ReconMode mode = parseReconMode(at(f, "reconstruction"));
    const auto filter = makeFilter(at(f, "filter"), std::stof(at(f, "radius")));
    const size_t j = at(f, "target") == "box:0.5" ? 0 : 1;
    std::vector<double> e;
    double scale = 0;  // the largest mean square before the references' variance is subtracted
    for (const Offset& off : offsets) {
      double raw = 0;
      e.push_back(mseAgainst(reconstruct(off.grid.at(spp), *filter, mode, 1).image, off.refs.images[j], raw));
      scale = std::max(scale, raw);
    }
    double mean = 0, ss = 0;
    for (double v : e) mean += v / e.size();
    for (double v : e) ss += (v - mean) * (v - mean);
    const double sd = std::sqrt(ss / (e.size() - 1)), se = sd / std::sqrt(double(e.size()));
    const std::string where = at(f, "filter") + " " + at(f, "radius") + " " + at(f, "reconstruction") + " spp " +
                              at(f, "spp") + " " + at(f, "target");
    EXPECT_EQ(at(f, "align_offsets"), "4") << where;
    // The two paths differ only in float rounding of the camera ray (a shifted screen point against a moved
    // centre; the grating is smooth): the numbers agree to about 2e-6 of the mean squares (2e-5 at worst).
    const double tol = 1e-4 * scale;
    EXPECT_NEAR(std::stod(at(f, "align_mse_target")), mean, tol) << where;
    EXPECT_NEAR(std::stod(at(f, "align_mse_target_sd")), sd, 2 * tol) << where;
    EXPECT_NEAR(std::stod(at(f, "align_mse_target_se")), se, 2 * tol) << where;
    std::stringstream values(at(f, "align_mse_target_offsets"));
    std::string v;
    size_t count = 0;
    for (; std::getline(values, v, ';'); ++count) {
      ASSERT_LT(count, e.size());
      EXPECT_NEAR(std::stod(v), e[count], tol) << where << " offset " << count;
    }
    EXPECT_EQ(count, e.size()) << where;
    // At 4 spp all of the grid's error is alignment: the spread over offsets is of the order of the mean.
    if (spp == 4) EXPECT_GT(sd, 0.2 * mean) << where;
    ++checked;
  }
  // uniform: spp 4 and 16 x (box 0.5, box 1, gaussian 1, gaussian 1.5, + supersample box 0.5) x 2 targets
  EXPECT_EQ(checked, 2u * 5 * 2);
  EXPECT_EQ(empty, 2u * 4 * 2);
  // The offset references are cached, their manifests record the offset.
  std::ifstream manifest(fs::path(c.out) / "references" / "alignment" / "grating-1.json");
  std::stringstream text;
  text << manifest.rdbuf();
  EXPECT_NE(text.str().find("\"film_offset\": ["), std::string::npos) << text.str();
}

TEST(SweepAlignment, OtherColumnsUnchangedThreadsShardsAndResume) {
  const auto plain = sweep(study("plain", 0, 1));
  const auto one = sweep(study("one", 4, 1)), two = sweep(study("two", 4, 2));
  ASSERT_EQ(one.size(), plain.size());
  ASSERT_EQ(two.size(), plain.size());
  for (size_t r = 0; r < plain.size(); ++r)
    for (size_t i = 0; i < plain[r].size(); ++i) {
      if (variable(i)) continue;
      EXPECT_EQ(two[r][i], one[r][i]) << "row " << r << " " << csvColumns()[i];
      if (!alignmentColumn(i)) EXPECT_EQ(plain[r][i], one[r][i]) << "row " << r << " " << csvColumns()[i];
      else EXPECT_EQ(plain[r][i], "") << "row " << r << " " << csvColumns()[i];
    }
  // Shards merge into the whole.
  const std::vector<std::string> shards = aliaslab::testing::runShards(study("sharded", 4, 1), 2);
  const std::string merged = (scratch() / "sharded" / "merged.csv").string();
  mergeStudy(merged, shards, "test");
  const auto m = readRows(merged);
  ASSERT_EQ(m.size(), one.size());
  for (size_t r = 0; r < m.size(); ++r)
    for (size_t i = 0; i < m[r].size(); ++i)
      if (!variable(i)) EXPECT_EQ(m[r][i], one[r][i]) << "row " << r << " " << csvColumns()[i];
  // Resume: lose every third row (one target row of some grid configurations), run again.
  const StudyConfig c = study("one", 4, 1);
  std::ifstream in(csvPath(c));
  std::string header, line, kept;
  std::getline(in, header);
  for (int n = 0; std::getline(in, line); ++n)
    if (n % 3) kept += line + "\n";
  in.close();
  std::ofstream(csvPath(c)) << header << "\n" << kept;
  const auto resumed = sweep(c);
  ASSERT_EQ(resumed.size(), one.size());
  for (size_t r = 0; r < resumed.size(); ++r)
    for (size_t i = 0; i < resumed[r].size(); ++i)
      if (!variable(i)) EXPECT_EQ(resumed[r][i], one[r][i]) << "row " << r << " " << csvColumns()[i];
  // A CSV holds one study: another K, or none, is refused before anything is written.
  EXPECT_THROW(runSweep(study("one", 3, 1)), OptionError);
  EXPECT_THROW(runSweep(study("one", 0, 1)), OptionError);
  EXPECT_THROW(runSweep(study("plain", 4, 1)), OptionError);
}

TEST(SweepAlignment, RefusesBadOffsets) {
  StudyConfig c = study("bad", 1, 1);
  EXPECT_THROW(runSweep(c), OptionError);
  c.alignOffsets = -1;
  EXPECT_THROW(runSweep(c), OptionError);
  c.alignOffsets = 4, c.alignRefSpp = 3;
  EXPECT_THROW(runSweep(c), OptionError);
  EXPECT_FALSE(fs::exists(scratch() / "bad" / "study.csv"));
  // Offsets differ from one another; offset k is the same every time.
  EXPECT_NE(alignmentOffset(0), alignmentOffset(1));
  EXPECT_EQ(alignmentOffset(3), alignmentOffset(3));
}

TEST(SweepAlignment, NaturalRadiusTokenAndColumn) {
  StudyConfig c;
  setStudyRadii(c, {"0.5", "1", "2", "natural"});
  EXPECT_EQ(c.radii, (std::vector<double>{0.5, 1, 2}));
  EXPECT_TRUE(c.naturalRadii);
  EXPECT_EQ(studyRadiusTokens(c), (std::vector<std::string>{"0.5", "1", "2", "natural"}));
  for (const char* bad : {"x", "natural,", "0", "-1", "nan", "inf", "1e999", "2px", ""})
    EXPECT_THROW(setStudyRadii(c, {"1", bad}), OptionError) << bad;
  EXPECT_THROW(setStudyRadii(c, {"natural", "natural"}), OptionError);
  EXPECT_THROW(setStudyRadii(c, {}), OptionError);
  setStudyRadii(c, {"natural"});  // every filter at its own radius only
  EXPECT_TRUE(c.radii.empty());
  c.filters = filterNames();
  c.classicBox = true;
  const std::vector<FilterSpec> only = studyFilters(c);
  ASSERT_EQ(only.size(), filterNames().size());
  for (const FilterSpec& s : only) EXPECT_EQ(s.second, defaultFilterRadius(s.first)) << s.first;
  // With radii: each (filter, radius) once; the registry's natural radii among them.
  setStudyRadii(c, {"0.5", "1", "2", "natural"});
  const std::vector<FilterSpec> all = studyFilters(c);
  std::set<FilterSpec> unique(all.begin(), all.end());
  EXPECT_EQ(unique.size(), all.size());
  EXPECT_TRUE(unique.count({"gaussian", 1.5}));
  EXPECT_TRUE(unique.count({"lanczos", 3.0}));
  EXPECT_TRUE(unique.count({"tent", 1.0}));
  EXPECT_EQ(all.size(), filterNames().size() * 3 + 3);  // 1.5 for gaussian, 3 for lanczos and hann
  // The column: the registry's natural radius of the row's filter.
  const auto rows = sweep(study("natural", 0, 1));
  ASSERT_FALSE(rows.empty());
  for (const auto& f : rows)
    EXPECT_EQ(std::stod(at(f, "natural_radius")), defaultFilterRadius(at(f, "filter"))) << at(f, "filter");
}

}  // namespace
}  // namespace aliaslab
