// The sweep's command line: every option bound to a SweepArgs, for the two parses of main.cpp (the first only
// learns the preset, which fills the StudyConfig before the second binds the options over it, so explicit options
// override the preset in every form: --preset X, --preset=X, or preset = X in a --config file).
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "study/config.h"

namespace aliaslab {

/// What the options set: the study, and the options main.cpp turns into it after parsing.
struct SweepArgs {
  StudyConfig c;
  std::string preset, shard, motion;
  std::vector<int> size;
  std::vector<std::string> merge;
  std::vector<std::string> radii;  ///< tokens ("natural" among them); bound with c's radii as its default
  bool imagesOn = false, imagesOff = false, quiet = false;
};

/// Adds every sweep option (and --config) to `app`, bound to `a`; the defaults shown are a.c's (set a preset first).
void addSweepOptions(CLI::App& app, SweepArgs& a);

/// The preset the command line names, in any form (empty: none, or a command line the real parse will refuse).
std::string commandLinePreset(int argc, char** argv);

}  // namespace aliaslab
