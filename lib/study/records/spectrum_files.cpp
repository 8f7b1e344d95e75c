#include "study/records/spectrum_files.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/files.h"
#include "core/format.h"
#include "core/gzip.h"
#include "study/records/csv.h"
#include "study/records/spectrum_key.h"
#include "study/study_scene.h"  // readFileBytes

namespace aliaslab {

const std::string& spectrumCsvHeader() {
  static const std::string h = [] {
    std::string columns;
    for (const std::string& c : spectrumKeyColumns()) columns += c + ',';
    return columns + "kind,bin,frequency,power,energy";
  }();
  return h;
}

namespace {
/// Complete lines of a spectrum CSV (header checked; a torn last line dropped).
std::vector<std::string> readSpectrumLines(const std::string& path, bool& any) {
  requireRegularFile(path, "a spectrum CSV is a regular file");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  if (in) ss << in.rdbuf();
  const std::string text = ss.str();
  std::vector<std::string> lines;
  any = !text.empty();
  size_t start = 0;
  bool header = true;
  for (size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1) {
    const std::string line = text.substr(start, nl - start);
    if (header) {
      if (line != spectrumCsvHeader()) throw FileError(path, "not a spectrum CSV (unexpected header)");
      header = false;
    } else if (!line.empty()) {
      lines.push_back(line);
    }
  }
  return lines;
}
}  // namespace

void appendSpectrumCsv(const std::string& path, const std::string& keyFields, const SpectrumMetrics& m) {
  appendSpectrumCsv(path, {{keyFields, &m}});
}

void appendSpectrumCsv(const std::string& path,
                       const std::vector<std::pair<std::string, const SpectrumMetrics*>>& configurations) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) {
    bool any = false;
    readSpectrumLines(path, any);  // checks the header
    std::ifstream in(path, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t keep = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
    if (keep != text.size()) std::filesystem::resize_file(path, keep, ec);  // a torn last line
    if (ec) throw FileError(path, "cannot truncate the partial last line: " + ec.message());
  }
  std::string out;
  const bool fresh = !std::filesystem::exists(path, ec) || std::filesystem::file_size(path, ec) == 0;
  if (fresh) out = spectrumCsvHeader() + '\n';
  for (const auto& [keyFields, mp] : configurations) {
    const SpectrumMetrics& m = *mp;
    for (const auto& [kind, s] :
         {std::pair<const char*, const RadialSpectrum*>{"error", &m.error}, {"noise", &m.noise}})
      for (int b = 0; b < kSpectrumBins; ++b)
        if (s->count[b] > 0)
          out += keyFields + ',' + kind + ',' + std::to_string(b) + ',' + formatReal(RadialSpectrum::frequency(b)) +
                 ',' + formatReal(s->power(b)) + ',' + formatReal(s->energy[b]) + '\n';
  }
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) throw FileError(path, "cannot open for appending: " + lastSystemError());
  std::string why = writeFully(fd, out);
  if (why.empty() && ::fdatasync(fd) != 0) why = lastSystemError();
  ::close(fd);
  if (!why.empty()) throw FileError(path, "write failed: " + why);
}

void canonicaliseSpectrumCsv(const std::string& path) {
  bool any = false;
  const auto lines = readSpectrumLines(path, any);
  // key: every field before power (scene .. frequency); the last copy wins; fields compare as numbers when
  // both are numbers that differ, else as text; a key that is a prefix of another (in fields) sorts first.
  // Each key is split and parsed once (a comparison then costs no allocation).
  struct Field {
    std::string text;
    bool number;
    double value;
  };
  struct Key {
    std::vector<Field> fields;
    size_t size;   ///< length of the key text
    size_t index;  ///< line number: the last copy of a key wins
  };
  std::vector<Key> keys(lines.size());
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    size_t cut = l.size();
    for (int commas = 0; commas < 2 && cut != std::string::npos; ++commas) cut = l.rfind(',', cut - 1);
    const std::string key = l.substr(0, cut);
    Key& k = keys[i];
    k.size = key.size(), k.index = i;
    for (size_t start = 0; start < key.size();) {  // the fields std::getline(.., ',') yields
      const size_t comma = std::min(key.find(',', start), key.size());
      Field f{key.substr(start, comma - start), false, 0.0};
      char* end = nullptr;
      f.value = std::strtod(f.text.c_str(), &end);
      f.number = !f.text.empty() && *end == 0;
      k.fields.push_back(std::move(f));
      start = comma + 1;
    }
  }
  const auto less = [](const Key& x, const Key& y) {
    for (size_t i = 0; i < x.fields.size() && i < y.fields.size(); ++i) {
      const Field &a = x.fields[i], &b = y.fields[i];
      if (a.text == b.text) continue;
      if (a.number && b.number && a.value != b.value) return a.value < b.value;
      return a.text < b.text;
    }
    return x.size < y.size;
  };
  std::stable_sort(keys.begin(), keys.end(), less);  // equal keys stay in file order
  std::string text = spectrumCsvHeader() + '\n';
  for (size_t i = 0; i < keys.size(); ++i)
    if (i + 1 == keys.size() || less(keys[i], keys[i + 1])) text += lines[keys[i].index] + '\n';  // last copy
  writeTextFile(path, text);
}

std::string spectrumCsvPath(const std::string& studyCsv, const std::string& scene) {
  const std::filesystem::path csv(withoutGzipSuffix(studyCsv));  // study.csv.gz's spectra are study.csv's
  const std::string stem = csv.filename() == "study.csv" ? "" : "." + csv.stem().string();
  return (csv.parent_path() / "spectra" / (scene + stem + ".csv")).string();
}

namespace {
const std::string kDamaged = ": the spectra are damaged or were never finished; rerun the sweep command that made "
                             "them (it measures the missing spectra again)";

// Per configuration (its key fields), per kind, its bins ("0;1;...;") of the complete lines of `text` (a torn last
// line ignored). Throws FileError on a line that is not a spectrum line.
std::map<std::string, std::map<std::string, std::string>> spectrumBlocks(const std::string& path, const std::string& text) {
  std::map<std::string, std::map<std::string, std::string>> bins;
  size_t start = 0;
  int lineNo = 0;
  for (size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1) {
    const std::string line = text.substr(start, nl - start);
    if (++lineNo == 1) {
      if (line != spectrumCsvHeader()) throw FileError(path, "line 1: not a spectrum CSV (unexpected header)");
      continue;
    }
    if (line.empty()) continue;
    std::vector<std::string> f;
    for (size_t a = 0;;) {
      const size_t comma = line.find(',', a);
      f.push_back(line.substr(a, comma == std::string::npos ? std::string::npos : comma - a));
      if (comma == std::string::npos) break;
      a = comma + 1;
    }
    const size_t kind = spectrumKeyColumns().size();  // the fields after the key: kind,bin,frequency,power,energy
    if (f.size() != kind + 5 || (f[kind] != "error" && f[kind] != "noise"))
      throw FileError(path, "line " + std::to_string(lineNo) + ": not a spectrum line (" + std::to_string(f.size()) +
                                " fields, expected " + std::to_string(kind + 5) + " with kind error or noise)" +
                                kDamaged);
    bins[spectrumKeyOfLine(f)][f[kind]] += f[kind + 1] + ';';
  }
  return bins;
}

// The bins most configurations of `blocks` have (every block of a scene has the same: one image size).
std::string usualBins(const std::map<std::string, std::map<std::string, std::string>>& blocks) {
  std::map<std::string, int> votes;
  for (const auto& [key, kinds] : blocks)
    for (const auto& [kind, b] : kinds) ++votes[b];
  std::string best;
  int most = 0;
  for (const auto& [b, n] : votes)
    if (n > most) best = b, most = n;
  return best;
}
}  // namespace

void checkSpectrumFile(const std::string& path, const std::vector<std::string>& configurations) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw FileError(path, "missing: its study CSV holds rows of this scene" + kDamaged);
  requireRegularFile(path, "a spectrum CSV is a regular file");
  const std::string text = readFileBytes(path);
  if (text.empty()) throw FileError(path, "is empty (0 bytes)" + kDamaged);
  if (text.back() != '\n') throw FileError(path, "cut last line (no newline at the end)" + kDamaged);
  const auto blocks = spectrumBlocks(path, text);
  const std::string usual = usualBins(blocks);
  for (const auto& [key, kinds] : blocks)
    for (const char* kind : {"error", "noise"}) {
      const auto it = kinds.find(kind);
      if (it == kinds.end()) throw FileError(path, "configuration " + key + " has no " + kind + " spectrum" + kDamaged);
      if (it->second != usual)
        throw FileError(path, "configuration " + key + " has another set of " + kind +
                                  " bins than the file's other spectra (a cut or damaged block)" + kDamaged);
    }
  for (const std::string& c : configurations)
    if (!blocks.count(c))
      throw FileError(path, "lacks the spectra of configuration " + c + ", which its study CSV holds" + kDamaged);
}

std::set<std::string> completeSpectra(const std::string& path, std::set<std::string>* present) {
  std::error_code ec;
  std::set<std::string> done;
  if (!std::filesystem::exists(path, ec)) return done;
  requireRegularFile(path, "a spectrum CSV is a regular file");
  const auto blocks = spectrumBlocks(path, readFileBytes(path));
  const std::string usual = usualBins(blocks);
  for (const auto& [key, kinds] : blocks) {
    if (present) present->insert(key);
    if (kinds.size() == 2 && kinds.at("error") == usual && kinds.at("noise") == usual) done.insert(key);
  }
  return done;
}

void checkShardSpectra(const std::vector<std::string>& inputs) {
  for (const std::string& input : inputs) {
    std::map<std::string, std::vector<std::string>> configs;  // scene -> configurations of the CSV
    for (const std::string& l : readCsvLines(input)) {
      const auto f = splitCsvLine(l);
      if (!isStudyRow(f)) continue;
      auto& v = configs[f[csvColumn("scene")]];
      const std::string key = spectrumKeyOfCsvRow(f);
      if (v.empty() || v.back() != key) v.push_back(key);
    }
    for (const auto& [scene, keys] : configs) checkSpectrumFile(spectrumCsvPath(input, scene), keys);
  }
}

std::vector<std::string> mergeSpectrumFiles(const std::string& out, const std::vector<std::string>& inputs) {
  namespace fs = std::filesystem;
  checkShardSpectra(inputs);  // every shard's spectra whole and complete for its rows, before anything is written
  std::map<std::string, std::vector<std::string>> byScene;  // scene -> lines of every shard
  for (const std::string& input : inputs) {
    const fs::path dir = fs::path(input).parent_path() / "spectra";
    // this shard's files end in "<suffix>": ".<stem>.csv", or just ".csv" for a study.csv (then the scene
    // name has no dot, which tells them from other shards' files in the same folder)
    const std::string probe = spectrumCsvPath(input, "X");
    const std::string suffix = fs::path(probe).filename().string().substr(1);
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir, ec)) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) {
      const std::string name = f.filename().string();
      if (name.size() <= suffix.size() || name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
        continue;
      const std::string scene = name.substr(0, name.size() - suffix.size());
      if (suffix == ".csv" && scene.find('.') != std::string::npos) continue;
      if (name.find(".partial.") != std::string::npos) continue;
      bool any = false;
      auto lines = readSpectrumLines(f.string(), any);
      auto& all = byScene[scene];
      all.insert(all.end(), lines.begin(), lines.end());
    }
  }
  std::vector<std::string> written;
  for (const auto& [scene, lines] : byScene) {
    const std::string path = spectrumCsvPath(out, scene);
    fs::create_directories(fs::path(path).parent_path());
    std::string text = spectrumCsvHeader() + '\n';
    for (const std::string& l : lines) text += l + '\n';
    writeTextFile(path, text);
    canonicaliseSpectrumCsv(path);
    written.push_back(path);
  }
  return written;
}

}  // namespace aliaslab
