// libFuzzer target: the scene parser on arbitrary text.
// InputError (ParseError, FileError, OptionError from a factory) is the
// expected answer to bad input; anything else (another exception, a crash,
// a sanitizer report) is a finding. TriangleMesh names resolve in a scratch
// folder under /dev/shm that holds a one-triangle stand-in for every
// scenes/meshes/*.obj (same relative names, so the seeds copied from
// scenes/*.txt load a mesh; the loader itself is fuzzed by fuzz_obj, and
// loading the 140 KB knot on every run would cost most of the time).
#include "aliaslab_paths.h"
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "fuzz_entry.h"
#include "scene/scene.h"

namespace aliaslab::fuzz {
namespace {
const std::string& sceneBaseDir() {
  namespace fs = std::filesystem;
  static const ScratchPath dir = [] {
    const fs::path d = "/dev/shm/aliaslab_fuzz_scene_" + std::to_string(::getpid());
    fs::create_directories(d / "meshes");
    for (const auto& e : fs::directory_iterator(ALIASLAB_SOURCE_DIR "/scenes/meshes"))
      std::ofstream(d / "meshes" / e.path().filename()) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    return ScratchPath{d.string()};
  }();
  return dir.path;
}
}  // namespace

void fuzzScene(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const Scene scene = parseSceneText(text, "fuzz.txt", sceneBaseDir());
    ALIASLAB_FUZZ_CHECK(scene.camera && scene.root);
  } catch (const InputError&) {
  }
}

}  // namespace aliaslab::fuzz

ALIASLAB_FUZZ_TARGET(aliaslab::fuzz::fuzzScene)
