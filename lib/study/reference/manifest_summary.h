// What a reference manifest says, as (field, value) pairs for a reader (the
// inspect program prints them). A manifest is the JSON the reference cache
// and the reference program write beside the images (study/reference/manifest.h, whose reader this uses): the
// study-wide fields (scene, scene_path, width, height,
// tracing, spp, sampler, seed, git_revision) and one line per filter entry
// (filter, radius, describe, ref_error, undefined_pixels, image).
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace aliaslab {

/// The fields of the manifest text `json` (read from `path`) that are present, in the order above; of the filter
/// entries only those that name `image` (every entry when `image` is empty: a set manifest lists several). Throws
/// FileError naming `path` when the text is not a manifest.
std::vector<std::pair<std::string, std::string>> manifestSummary(const std::string& json, const std::string& image,
                                                                 const std::string& path);

}  // namespace aliaslab
