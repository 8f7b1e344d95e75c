// What makes the rows of CSVs one study: the values every row of a study shares.
//
// A study fixes, for all its rows, the seeds K, the reference spp, the frames
// and the motion (a study with frames), the fixed grid's alignment offsets
// and the list of targets (one row per configuration and target), and for
// each scene its image size. A resumed CSV is checked against the options of
// the run (study/validate.h checkSameStudy); shards being merged are checked
// against each other here (study/records/merge.h): the same values, read from the
// rows, so shards made with other options are refused, not merged.
#pragma once
#include <map>
#include <set>
#include <string>
#include <vector>

namespace aliaslab {

/// The study-wide values of a CSV's data lines: name -> the values its rows hold ("seeds" -> {"8"}, "targets"
/// -> {"box:0.5,gaussian:1.5"}, "size of zoneplate" -> {"48 x 48"}, "frames and motion" -> {"4 frames, motion
/// 0.25,0"}, "alignment offsets" -> {"8"}). A name absent: no row tells (e.g. no fixed-grid row).
using StudyIdentity = std::map<std::string, std::set<std::string>>;
StudyIdentity studyIdentity(const std::vector<std::string>& lines);

/// "" when `a` and `b` can be rows of one study (every name both hold, one value each and the same); else what
/// differs, naming each side's value: "seeds 2 in <nameA>, 3 in <nameB>".
std::string studyDifference(const StudyIdentity& a, const std::string& nameA, const StudyIdentity& b,
                            const std::string& nameB);

}  // namespace aliaslab
