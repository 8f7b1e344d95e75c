// What built this program: the git revision of the source tree (with
// "-dirty" when it had uncommitted changes) and the CMake build type, for
// every front end's --version and for manifests.
#pragma once
#include <string>

namespace aliaslab {

/// The revision built (at build time, unlike study/reference/reference.h gitRevision at run time),
/// e.g. "b40d151a2c3e" or "b40d151a2c3e-dirty"; "unknown" outside a git checkout.
std::string buildRevision();
/// CMAKE_BUILD_TYPE, e.g. "Release".
std::string buildType();
/// "<program> (aliaslab) git <revision>, <build type> build".
std::string versionLine(const std::string& program);

}  // namespace aliaslab
