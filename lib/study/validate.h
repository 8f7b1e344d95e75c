// Checking a study before any work, and checking that a resumed CSV holds the same study.
//
// The protocol: the sweep calls validateStudy(config) first. It checks every
// name, number and list of the StudyConfig (each name through its factory,
// so the messages list the valid names), the reference options, every scene
// (present, parseable, its size read from the `# render:` line: no
// acceleration structure is built), the memory the largest group needs and
// the output folders (created if missing, removed again when a later check
// fails). Nothing is rendered or written before it returns; it returns the
// StudyPlan it checked, so the sweep expands and parses nothing twice.
// When the sweep resumes a CSV, checkSameStudy / checkSameSceneSize refuse
// rows made with other values (a CSV holds one study).
//
// Errors: OptionError keyed by the StudyConfig field ("samplers", "radii",
// "ref-sampler", "size", "out", ...; a factory's own key such as "sampler"
// or "filter" is re-keyed to the list it came from), FileError for files.
// Messages that name another parameter write its key in braces ("{out}").
#pragma once
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "study/config.h"

namespace aliaslab {

/// A validated study: what validateStudy checked, ready to run.
struct StudyPlan {
  FilterCache filters;          ///< every filter of the study, built once: the rows', the targets' and the area's
  std::vector<Target> targets;  ///< parsed once, in order (the first is the primary)
  StudyFilter area;             ///< the pixel-area reference's filter (kAreaSpec)
  std::vector<SampleSetGroup> groups;  ///< every group in canonical order (unsharded), filters built
  std::vector<std::string> notes;      ///< skipped combinations
  std::map<std::string, SceneSize> sceneSizes;  ///< per scene file: its size in this study (render line, overrides)
};

/// Checks names, numbers, the reference options, scenes (existence, parse and
/// size from the render line; no acceleration structure is built), memory and
/// the output folders (created if missing, must be writable). Throws InputError.
/// Returns the plan it checked (targets parsed, groups expanded, filters built).
StudyPlan validateStudy(const StudyConfig& config);

/// Creates every (folder, key) that is missing and checks that it is writable; when one fails, the folders
/// created before it are removed again (nothing is left behind) and OptionError(key) is thrown.
void requireOutputFolders(const std::vector<std::pair<std::string, std::string>>& folders);

/// A CSV holds one study: throws OptionError keyed "seeds", "ref-spp", "frames", "motion" or "target" when a row of
/// the existing CSV `lines` was made with another value than `config` and its parsed `targets` ask for (a rerun
/// would add a second copy).
void checkSameStudy(const std::string& csv, const std::vector<std::string>& lines, const StudyConfig& config,
                    const std::vector<Target>& targets);
/// The same for the image size of one scene (OptionError "size").
void checkSameSceneSize(const std::string& csv, const std::vector<std::string>& lines, const std::string& stem,
                        int width, int height);

}  // namespace aliaslab
