// libFuzzer target: the OBJ loader on arbitrary bytes. The bytes go to one
// fixed file per process under /dev/shm (RAM, removed at exit); InputError
// is the expected answer to bad input, anything else is a finding.
#include <unistd.h>

#include <cstdio>

#include "core/error.h"
#include "fuzz_entry.h"
#include "geometry/primitives.h"

namespace aliaslab::fuzz {
namespace {
const std::string& objPath() {
  static const ScratchPath file{"/dev/shm/aliaslab_fuzz_obj_" + std::to_string(::getpid()) + ".obj"};
  return file.path;
}
}  // namespace

void fuzzObj(const uint8_t* data, size_t size) {
  const std::string& path = objPath();
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ALIASLAB_FUZZ_CHECK(f != nullptr);
  const size_t written = size ? std::fwrite(data, 1, size, f) : 0;
  std::fclose(f);
  ALIASLAB_FUZZ_CHECK(written == size);
  try {
    auto mesh = loadObj(path, nullptr);
    // A mesh that loads has at least one triangle, each with finite bounds.
    ALIASLAB_FUZZ_CHECK(mesh && !mesh->children.empty());
    for (const auto& t : mesh->children) ALIASLAB_FUZZ_CHECK(t->bounds().finite());
  } catch (const InputError&) {
  }
}

}  // namespace aliaslab::fuzz

ALIASLAB_FUZZ_TARGET(aliaslab::fuzz::fuzzObj)
