// The spectrum key (study/records/spectrum_key.h): a configuration's key is the same whether it is made from its
// CsvRow (the sweep writing its spectra), its study CSV line (resume, merge) or its spectrum lines (the files), and
// it is the first fields of the lines appendSpectrumCsv writes. Expected keys are written out by hand.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "measure/spectrum.h"
#include "study/records/csv.h"
#include "study/records/spectrum_files.h"
#include "study/records/spectrum_key.h"
#include "support/scratch_dir.h"

namespace aliaslab {
namespace {

CsvRow row(const std::string& scene, const std::string& sampler, int spp, const std::string& filter, double radius,
           const std::string& recon, const std::string& prefilter) {
  CsvRow r;
  r.scene = scene, r.sampler = sampler, r.spp = spp, r.filter = filter, r.radius = radius;
  r.reconstruction = recon, r.prefilter = prefilter;
  r.filterParams = "B = 1/3, C = 1/3";  // a quoted field with commas before the key's last columns
  r.target = "box:0.5";
  return r;
}

TEST(SpectrumKey, ColumnsAreTheSpectrumHeadersFirstAndStudyColumns) {
  const std::vector<std::string> expected = {"scene", "sampler", "spp", "filter", "radius", "reconstruction",
                                             "prefilter"};
  EXPECT_EQ(spectrumKeyColumns(), expected);
  EXPECT_EQ(spectrumCsvHeader(),
            "scene,sampler,spp,filter,radius,reconstruction,prefilter,kind,bin,frequency,power,energy");
  for (const std::string& c : spectrumKeyColumns()) EXPECT_NO_THROW(csvColumn(c)) << c;
}

TEST(SpectrumKey, RowCsvLineAndSpectrumLineGiveTheSameKey) {
  struct Case {
    CsvRow r;
    std::string key;
  };
  const std::vector<Case> cases = {
      {row("fence", "jittered", 4, "box", 0.5, "weighted", "none"), "fence,jittered,4,box,0.5,weighted,none"},
      {row("zoneplate", "bluenoise-dither:random", 16, "mitchell", 1.0 / 3, "splat", "footprint"),
       "zoneplate,bluenoise-dither:random,16,mitchell,0.333333333,splat,footprint"},
      {row("s", "zsobol", 128, "gaussian", 1.5, "supersample", "none"), "s,zsobol,128,gaussian,1.5,supersample,none"}};
  const auto dir = testing::scratchDir("aliaslab_spectrum_key_test");
  const std::string path = (dir / "spectra.csv").string();
  const Image zero(8, 8);
  Image noise(8, 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) noise.set(x, y, Color(0.1f * ((x * 7 + y * 3) % 5), 0.f, 0.f));
  SpectrumAccumulator acc(RefEstimate{&zero}, {});
  acc.add(noise);
  acc.add(zero);
  const SpectrumMetrics m = acc.result();
  for (const Case& c : cases) {
    EXPECT_EQ(spectrumKeyOfRow(c.r), c.key);
    EXPECT_EQ(spectrumKeyOfCsvRow(splitCsvLine(formatCsvRow(c.r))), c.key);
    appendSpectrumCsv(path, spectrumKeyOfRow(c.r), m);
  }
  // Every line of the file starts with its configuration's key, and reads back as that key.
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  std::set<std::string> keys;
  int lines = 0;
  while (std::getline(in, line)) {
    const std::string key = spectrumKeyOfLine(splitCsvLine(line));
    EXPECT_EQ(line.rfind(key + ",", 0), 0u) << line;
    keys.insert(key), ++lines;
  }
  EXPECT_GT(lines, 0);
  std::set<std::string> expected;
  for (const Case& c : cases) expected.insert(c.key);
  EXPECT_EQ(keys, expected);
  EXPECT_EQ(completeSpectra(path), expected);  // the resume's reading finds every configuration whole
}

}  // namespace
}  // namespace aliaslab
