#include "study/reference/manifest_summary.h"

#include "study/reference/manifest.h"

namespace aliaslab {

std::vector<std::pair<std::string, std::string>> manifestSummary(const std::string& json, const std::string& image,
                                                                 const std::string& path) {
  const Manifest m = readManifest(json, path);
  std::vector<std::pair<std::string, std::string>> out;
  for (const char* k : {"scene", "scene_path", "width", "height", "tracing", "spp", "sampler", "seed", "git_revision"})
    if (std::string v = manifestValue(m.head, k); !v.empty()) out.emplace_back(k, std::move(v));
  // the filter entry of this image (a set manifest lists several): one with a field whose value is `image`
  for (const ManifestFields& entry : m.filters) {
    bool named = image.empty();
    for (const ManifestField& f : entry) named = named || f.value == image;
    if (named)
      for (const char* k : {"filter", "radius", "describe", "ref_error", "undefined_pixels", "image"})
        if (std::string v = manifestValue(entry, k); !v.empty()) out.emplace_back(k, std::move(v));
  }
  return out;
}

}  // namespace aliaslab
