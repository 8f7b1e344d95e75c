#include "core/version.h"

#include "aliaslab_version.h"

namespace aliaslab {

std::string buildRevision() { return ALIASLAB_GIT_REVISION; }
std::string buildType() { return ALIASLAB_BUILD_TYPE; }
std::string versionLine(const std::string& program) {
  return program + " (aliaslab) git " + buildRevision() + ", " + buildType() + " build";
}

}  // namespace aliaslab
