#include "core/files.h"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>

#include "core/error.h"

namespace aliaslab {

std::string temporaryPathFor(const std::string& path) {
  static std::atomic<unsigned long> counter{0};
  return path + ".partial." + std::to_string(::getpid()) + "." + std::to_string(counter++) +
         std::filesystem::path(path).extension().string();
}

void writeTextFile(const std::string& path, const std::string& text) {
  const std::string tmp = temporaryPathFor(path);
  std::error_code ec;
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw FileError(path, "cannot open for writing");
    out << text;
    if (!out.flush()) {
      out.close();
      std::filesystem::remove(tmp, ec);
      throw FileError(path, "write failed");
    }
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw FileError(path, "cannot move the finished file into place: " + ec.message());
  }
}

}  // namespace aliaslab
