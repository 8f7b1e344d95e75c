#include "study/merge.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>

#include "core/error.h"
#include "study/contact.h"
#include "study/csv.h"
#include "study/lock.h"
#include "study/spectrum_files.h"

namespace aliaslab {

namespace fs = std::filesystem;

void checkShardSet(const std::vector<std::string>& inputs) {
  static const std::regex name(R"(shard-(\d+)-of-(\d+)\.csv$)");
  std::map<int, std::vector<int>> seen;  // N -> the i given
  for (const std::string& in : inputs) {
    std::smatch m;
    const std::string file = fs::path(in).filename().string();
    if (!std::regex_search(file, m, name)) continue;
    try {
      seen[std::stoi(m[2].str())].push_back(std::stoi(m[1].str()));
    } catch (const std::exception&) {
      throw OptionError("merge", "shard number out of range in '" + in + "'");
    }
  }
  if (seen.size() > 1)
    throw OptionError("merge", "the inputs are shards of different splits (" + std::to_string(seen.begin()->first) +
                                     " and " + std::to_string(seen.rbegin()->first) + " shards)");
  for (auto& [count, given] : seen) {
    std::sort(given.begin(), given.end());
    for (int i = 0; i < count; ++i)
      if (!std::binary_search(given.begin(), given.end(), i))
        throw OptionError("merge", "shard " + std::to_string(i) + " of " + std::to_string(count) +
                                         " is missing (study.shard-" + std::to_string(i) + "-of-" +
                                         std::to_string(count) + ".csv); the merge would lack its rows");
    if (given.back() >= count || std::adjacent_find(given.begin(), given.end()) != given.end())
      throw OptionError("merge", "shard files of " + std::to_string(count) +
                                       " shards given twice or numbered beyond N-1");
  }
}

void mergeStudy(const std::string& out, const std::vector<std::string>& inputs, const std::string& command) {
  checkShardSet(inputs);
  const CsvLock lock(out, command);
  mergeCsvFiles(out, inputs);
  mergeSpectrumFiles(out, inputs);  // the shards' spectra (spectra/<scene>.<shard>.csv) into the merged CSV's
  // Contact sheets of the whole study when the shards wrote images beside it.
  const fs::path images = fs::path(out).parent_path() / "images";
  if (fs::is_directory(images)) writeContactSheets(out, images.string());
}

}  // namespace aliaslab
