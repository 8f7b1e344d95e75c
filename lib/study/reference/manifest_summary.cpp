#include "study/reference/manifest_summary.h"

#include <regex>
#include <sstream>

namespace aliaslab {

namespace {
/// The value of "key": in a manifest (a string without quotes, or a number), "" when absent.
std::string field(const std::string& json, const std::string& key) {
  std::smatch m;
  const std::regex re("\"" + key + "\":\\s*(\"([^\"]*)\"|[-+0-9.eE]+)");
  if (!std::regex_search(json, m, re)) return "";
  return m[2].matched ? m[2].str() : m[1].str();
}
}  // namespace

std::vector<std::pair<std::string, std::string>> manifestSummary(const std::string& json, const std::string& image) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const char* k : {"scene", "scene_path", "width", "height", "tracing", "spp", "sampler", "seed", "git_revision"})
    if (std::string v = field(json, k); !v.empty()) out.emplace_back(k, std::move(v));
  // the filter entry of this image (a set manifest lists several)
  std::istringstream lines(json);
  for (std::string line; std::getline(lines, line);)
    if (line.find("\"filter\"") != std::string::npos &&
        (image.empty() || line.find("\"" + image + "\"") != std::string::npos))
      for (const char* k : {"filter", "radius", "describe", "ref_error", "undefined_pixels", "image"})
        if (std::string v = field(line, k); !v.empty()) out.emplace_back(k, std::move(v));
  return out;
}

}  // namespace aliaslab
