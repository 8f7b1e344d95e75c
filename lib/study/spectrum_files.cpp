#include "study/spectrum_files.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "core/error.h"
#include "core/files.h"
#include "core/format.h"

namespace aliaslab {

const std::string& spectrumCsvHeader() {
  static const std::string h = "scene,sampler,spp,filter,radius,reconstruction,prefilter,kind,bin,frequency,power,energy";
  return h;
}

namespace {
std::string real(double v) { return formatNumber(v, "%.9g"); }

/// Complete lines of a spectrum CSV (header checked; a torn last line dropped).
std::vector<std::string> readSpectrumLines(const std::string& path, bool& any) {
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
          out += keyFields + ',' + kind + ',' + std::to_string(b) + ',' + real(RadialSpectrum::frequency(b)) + ',' +
                 real(s->power(b)) + ',' + real(s->energy[b]) + '\n';
  }
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd < 0) throw FileError(path, "cannot open for appending");
  const bool ok = ::write(fd, out.data(), out.size()) == static_cast<ssize_t>(out.size());
  ::close(fd);
  if (!ok) throw FileError(path, "write failed");
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
  const std::filesystem::path csv(studyCsv);
  const std::string stem = csv.filename() == "study.csv" ? "" : "." + csv.stem().string();
  return (csv.parent_path() / "spectra" / (scene + stem + ".csv")).string();
}

std::vector<std::string> mergeSpectrumFiles(const std::string& out, const std::vector<std::string>& inputs) {
  namespace fs = std::filesystem;
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
