#include "study/records/merge.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/files.h"
#include "core/gzip.h"
#include "study/records/csv.h"
#include "study/records/lock.h"
#include "study/records/spectrum_files.h"
#include "study/records/study_identity.h"
#include "study/study_scene.h"  // readFileBytes
#include "study/sweep/contact.h"

namespace aliaslab {

namespace fs = std::filesystem;

void checkShardSet(const std::vector<std::string>& inputs) {
  static const std::regex name(R"(shard-(\d+)-of-(\d+)\.csv(\.gz)?$)");
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

std::vector<std::string> readShardCsv(const std::string& path, bool allowNoRows, bool* motionOut) {
  bool motion = false;
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw FileError(path, "is a folder, not a shard CSV");
  if (!fs::exists(path, ec)) throw FileError(path, "no such shard CSV");
  requireRegularFile(path, "a shard CSV is read from a regular file");
  const std::string bytes = readFileBytes(path);
  std::string text = bytes;
  if (isGzipData(bytes)) {  // a gzipped shard (study/csv.h): a torn last member is an interrupted shard
    Gunzipped g = gunzipMembers(bytes);
    if (!g.damage.empty())
      throw FileError(path, g.damage + (g.cutShort ? ": the shard was interrupted; rerun its sweep command to "
                                                      "finish it, then merge" : ""));
    text = std::move(g.text);
  }
  if (bytes.empty()) throw FileError(path, "is empty (0 bytes): the shard was never written or was emptied");
  std::vector<std::string> lines;
  size_t start = 0;
  int lineNo = 0;
  while (start < text.size()) {
    ++lineNo;
    const size_t nl = text.find('\n', start);
    if (nl == std::string::npos)
      throw ParseError(path, lineNo, "cut line (no newline at the end): the shard was interrupted; rerun its "
                                     "sweep command to finish it, then merge");
    const std::string line = text.substr(start, nl - start);
    start = nl + 1;
    if (lineNo == 1) {
      if (line != csvHeader() && csvHeader().compare(0, line.size() + 1, line + ",") == 0)
        throw ParseError(path, 1, "written by an older sweep (its header lacks the column(s) " +
                                      csvHeader().substr(line.size() + 1) +
                                      "); shards of one study are made by one sweep: rerun this shard");
      motion = line == csvHeader(true);  // a study with frames (study/records/csv.h)
      if (line != csvHeader() && !motion) throw ParseError(path, 1, "not a study CSV (unexpected header)");
      continue;
    }
    if (line.empty()) continue;
    const size_t n = splitCsvLine(line).size();
    const size_t expected = csvColumnCount(motion);
    if (n != expected)
      throw ParseError(path, lineNo, "has " + std::to_string(n) + " fields, expected " + std::to_string(expected) +
                                         " (a damaged row)");
    lines.push_back(line);
  }
  if (lines.empty() && !allowNoRows) throw FileError(path, "holds no rows (header only): a shard of a study has at least one row");
  if (motionOut) *motionOut = motion;
  return lines;
}

namespace {
// The results of a row without the columns that legitimately differ between runs (timing, threads).
std::string measuredValues(const std::vector<std::string>& f) {
  std::string v;
  const auto timing = csvTimingColumns();
  for (size_t i = 0; i < f.size(); ++i)
    if (std::find(timing.begin(), timing.end(), i) == timing.end() &&
        (i >= csvColumns().size() || csvColumns()[i] != "threads"))
      v += f[i] + '\x1f';
  return v;
}
}  // namespace

void mergeCsvFiles(const std::string& out, const std::vector<std::string>& inputs,
                   const std::function<void()>& beforeWrite) {
  static const size_t kScene = csvColumn("scene"), kSampler = csvColumn("sampler"), kSpp = csvColumn("spp"),
                      kFilter = csvColumn("filter"), kRadius = csvColumn("radius"), kRecon = csvColumn("reconstruction"),
                      kTarget = csvColumn("target");
  std::vector<std::string> all;
  struct Origin {
    std::string file;
    size_t line;
    std::string values;
  };
  std::map<std::string, Origin> seen;  // key -> where it came from first
  refuseOutputsOverInputs({{"merge", out}, {"merge", CsvLock::lockPath(out)}}, inputs);
  // A shard with no rows is legitimate only when the study has fewer groups than shards: shard i holds the groups
  // g with g mod N == i, so then every non-empty shard holds exactly one (scene, sampler, spp) group and the
  // empty ones are the highest-numbered. Anything else means rows were lost.
  static const std::regex shardName(R"(shard-(\d+)-of-(\d+)\.csv(\.gz)?$)");
  std::vector<std::pair<int, std::string>> empty;  // (shard index, file)
  int highestWithRows = -1;
  bool severalGroups = false;
  std::optional<bool> motion;  // every shard the same kind: still, or with frames
  std::optional<std::pair<std::string, StudyIdentity>> first;  // the first shard with rows, and its study
  for (const std::string& in : inputs) {
    std::smatch m;
    const std::string file = fs::path(in).filename().string();
    const bool named = std::regex_search(file, m, shardName);
    bool moving = false;
    const auto lines = readShardCsv(in, named, &moving);
    if (motion && *motion != moving)
      throw FileError(in, "mixes a study with frames and a still one among the shards: merge the shards of one study");
    motion = moving;
    if (lines.empty()) {
      empty.emplace_back(std::stoi(m[1].str()), in);
      continue;
    }
    // One study: the values every row of a study shares, the same in every shard (as a resume checks them).
    const StudyIdentity id = studyIdentity(lines);
    if (!first) first = std::make_pair(in, id);
    if (const std::string diff = studyDifference(first->second, first->first, id, in); !diff.empty())
      throw OptionError("merge", (in == first->first ? in : in + " and " + first->first) +
                                     " hold different studies (" + diff +
                                     "): merge the shards of one study only (made with the same options)");
    std::set<std::string> groups;
    for (const std::string& l : lines) {
      const auto f = splitCsvLine(l);
      groups.insert(f[kScene] + '\x1f' + f[kSampler] + '\x1f' + f[kSpp]);
    }
    severalGroups = severalGroups || groups.size() > 1;
    if (named) highestWithRows = std::max(highestWithRows, std::stoi(m[1].str()));
    // Line numbers for messages (readShardCsv skips blank lines, so count them again here).
    std::istringstream text(readTextMaybeGzip(in, false));
    std::string l;
    size_t lineNo = 0, next = 0;
    while (next < lines.size() && std::getline(text, l)) {
      ++lineNo;
      if (lineNo == 1 || l != lines[next]) continue;
      const auto f = splitCsvLine(l);
      const std::string key = csvKey(f), values = measuredValues(f);
      const auto [it, fresh] = seen.emplace(key, Origin{in, lineNo, values});
      if (!fresh && it->second.values != values)
        throw FileError(in, "line " + std::to_string(lineNo) + " and " + it->second.file + " line " +
                                std::to_string(it->second.line) +
                                " give different results for the same configuration (" + f[kScene] + ", " +
                                f[kSampler] + " spp " + f[kSpp] + ", " + f[kFilter] + " r " + f[kRadius] + ", " +
                                f[kRecon] + ", target " + f[kTarget] + "): shards of different studies? Merge the shards of one study only");
      ++next;
    }
    all.insert(all.end(), lines.begin(), lines.end());
  }
  for (const auto& [index, file] : empty)
    if (severalGroups || index < highestWithRows || all.empty())
      throw FileError(file, "holds no rows (header only), but " +
                                std::string(all.empty() ? "no shard has rows"
                                                        : severalGroups ? "the study has more groups than shards"
                                                                        : "a higher-numbered shard has rows") +
                                ", so every shard must have rows: this shard was emptied or never ran; rerun it");
  if (beforeWrite) beforeWrite();
  writeCsvFile(out, sortCsvRows(std::move(all)), motion.value_or(false));
}

void mergeStudy(const std::string& out, const std::vector<std::string>& inputs, const std::string& command) {
  checkShardSet(inputs);
  // A device or FIFO (/dev/stdout, a pipe) receives the CSV only: no lock, spectra or contact sheets beside it.
  const bool stream = outputTarget(out).special;
  std::optional<CsvLock> lock;
  if (!stream) lock.emplace(out, command);
  mergeCsvFiles(out, inputs, [&] { checkShardSpectra(inputs); });  // every shard whole before anything is written
  if (stream) return;
  mergeSpectrumFiles(out, inputs);  // the shards' spectra (spectra/<scene>.<shard>.csv) into the merged CSV's
  // Contact sheets of the whole study when the shards wrote images beside it.
  const fs::path images = fs::path(out).parent_path() / "images";
  if (fs::is_directory(images)) writeContactSheets(out, images.string());
}

}  // namespace aliaslab
