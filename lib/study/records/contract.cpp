#include "study/records/contract.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <tuple>

#include "core/error.h"
#include "core/format.h"
#include "sampling/sampler.h"
#include "study/records/csv.h"

namespace aliaslab {

double ContractCheck::z() const {
  if (!(bound > 0) || !(se > 0) || !std::isfinite(se)) return std::numeric_limits<double>::quiet_NaN();
  return (ratio - bound) / se;
}

bool ContractCheck::violated() const {
  const double zz = z();
  return std::isfinite(zz) && zz > 3;
}

double claimedBound(const std::string& sampler, int spp) {
  try {
    return makeSampler(sampler, spp, 0)->varianceBound();
  } catch (const OptionError&) {
    return 0;  // not a pattern of the factory (an adaptive method): no theorem
  }
}

std::vector<ContractCheck> checkContract(const std::vector<ContractRow>& rows, const BoundOf& bound) {
  // (scene, spp) in the order first met, and random's row of each
  std::vector<std::pair<std::string, int>> cells;
  std::map<std::pair<std::string, int>, const ContractRow*> random;
  for (const ContractRow& r : rows) {
    const auto key = std::make_pair(r.scene, r.spp);
    if (std::find(cells.begin(), cells.end(), key) == cells.end()) cells.push_back(key);
    if (r.sampler == "random" && !random.count(key)) random[key] = &r;
  }
  std::vector<ContractCheck> out;
  for (const auto& key : cells) {
    const auto it = random.find(key);
    if (it == random.end() || !(it->second->noise > 0)) continue;
    const ContractRow& b = *it->second;
    std::set<std::string> seen;
    for (const ContractRow& a : rows) {
      if (a.scene != key.first || a.spp != key.second || a.sampler == "random" || !seen.insert(a.sampler).second)
        continue;
      ContractCheck c{a.scene, a.sampler, a.spp, a.noise / b.noise, 0, bound(a.sampler, a.spp)};
      // delta method for a ratio of independent estimates; a zero numerator (the fixed grid) keeps se 0
      const double ra = a.noise > 0 ? a.noiseSe / a.noise : 0, rb = b.noiseSe / b.noise;
      c.se = c.ratio * std::sqrt(ra * ra + rb * rb);
      out.push_back(c);
    }
  }
  return out;
}

std::vector<ContractRow> contractRows(const std::string& csvPath) {
  const std::vector<std::string> lines = readCsvLines(csvPath);
  const size_t scene = csvColumn("scene"), sampler = csvColumn("sampler"), spp = csvColumn("spp"),
               filter = csvColumn("filter"), radius = csvColumn("radius"), recon = csvColumn("reconstruction"),
               prefilter = csvColumn("prefilter"), noise = csvColumn("noise"), noiseSe = csvColumn("noise_se");
  std::vector<ContractRow> out;
  std::set<std::tuple<std::string, std::string, int>> seen;  // noise is the same on every target row
  for (const std::string& line : lines) {
    const std::vector<std::string> f = splitCsvLine(line);
    if (!isStudyRow(f) || f[filter] != "box" || f[recon] != "weighted" || f[prefilter] != "none") continue;
    try {
      if (std::abs(std::stod(f[radius]) - 0.5) > 1e-9) continue;
      ContractRow r{f[scene], f[sampler], std::stoi(f[spp]), std::stod(f[noise]), std::stod(f[noiseSe])};
      if (seen.insert({r.scene, r.sampler, r.spp}).second) out.push_back(r);
    } catch (const std::exception&) {
      throw FileError(csvPath, "a row's spp, radius, noise or noise_se is not a number: " + line);
    }
  }
  return out;
}

namespace {
std::string describeCheck(const ContractCheck& c) {
  return c.scene + ", " + c.sampler + " at " + std::to_string(c.spp) + " spp: noise " +
         formatNumber(c.ratio, "%.3g") + " +- " + formatNumber(c.se, "%.2g") + " x random's";
}
}  // namespace

std::vector<std::string> contractViolations(const std::vector<ContractCheck>& checks) {
  std::vector<std::string> out;
  for (const ContractCheck& c : checks)
    if (c.violated())
      out.push_back(describeCheck(c) + ", above its bound " + formatNumber(c.bound, "%.4g") + " by " +
                    formatNumber(c.z(), "%.1f") + " standard errors");
  return out;
}

std::string contractSummary(const std::vector<ContractCheck>& checks) {
  size_t bounded = 0, violated = 0;
  const ContractCheck* worst = nullptr;
  for (const ContractCheck& c : checks) {
    if (!(c.bound > 0)) continue;
    ++bounded, violated += c.violated();
    if (!worst || c.ratio / c.bound > worst->ratio / worst->bound) worst = &c;
  }
  std::string s = "sampler bounds (noise against random's at box r=0.5, docs/science.md): " + std::to_string(bounded) +
                  " check(s) with a bound, " + std::to_string(violated) + " violated beyond 3 se, " +
                  std::to_string(checks.size() - bounded) + " without a bound";
  if (worst) s += "; highest against its bound: " + describeCheck(*worst) + ", bound " + formatNumber(worst->bound, "%.4g");
  return s;
}

}  // namespace aliaslab
