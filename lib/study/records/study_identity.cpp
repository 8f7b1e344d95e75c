#include "study/records/study_identity.h"

#include "study/sweep/alignment.h"
#include "study/records/csv.h"

namespace aliaslab {

namespace {
std::string joined(const std::set<std::string>& values, const char* separator) {
  std::string s;
  for (const std::string& v : values) s += (s.empty() ? "" : separator) + v;
  return s;
}
}  // namespace

StudyIdentity studyIdentity(const std::vector<std::string>& lines) {
  static const size_t kScene = csvColumn("scene"), kWidth = csvColumn("width"), kHeight = csvColumn("height"),
                      kSampler = csvColumn("sampler"), kSeeds = csvColumn("seeds"), kRefSpp = csvColumn("ref_spp"),
                      kTarget = csvColumn("target"), kOffsets = csvColumn("align_offsets");
  const size_t m = csvColumns().size();  // the motion columns follow: frames, motion_dx, motion_dy (study/records/csv.h)
  StudyIdentity id;
  std::set<std::string> targets;
  for (const std::string& line : lines) {
    const auto f = splitCsvLine(line);
    if (!isStudyRow(f)) continue;
    id["seeds"].insert(f[kSeeds]);
    id["ref_spp"].insert(f[kRefSpp]);
    targets.insert(f[kTarget]);
    id["size of " + f[kScene]].insert(f[kWidth] + " x " + f[kHeight]);
    if (f[kSampler] == kFixedGridSampler)
      id["alignment offsets"].insert(f[kOffsets].empty() ? std::string("none") : f[kOffsets]);
    id["frames and motion"].insert(f.size() > m ? f[m] + " frames, motion " + f[m + 1] + "," + f[m + 2]
                                                : std::string("one frame (a still study)"));
  }
  if (!targets.empty()) id["targets"].insert(joined(targets, ","));
  return id;
}

std::string studyDifference(const StudyIdentity& a, const std::string& nameA, const StudyIdentity& b,
                            const std::string& nameB) {
  for (const auto* side : {&a, &b})
    for (const auto& [name, values] : *side)
      if (values.size() > 1)
        return name + " " + joined(values, " and ") + " in " + (side == &a ? nameA : nameB) + " alone";
  for (const auto& [name, values] : a) {
    const auto it = b.find(name);
    if (it != b.end() && it->second != values)
      return name + " " + *values.begin() + " in " + nameA + ", " + *it->second.begin() + " in " + nameB;
  }
  return {};
}

}  // namespace aliaslab
