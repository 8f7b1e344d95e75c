#include "study/spectrum.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <unsupported/Eigen/FFT>

#include "core/error.h"
#include "core/files.h"
#include "core/format.h"

namespace aliaslab {

namespace {
using Complex = std::complex<double>;
constexpr double kPi = 3.14159265358979323846;

/// The unnormalised 2-D DFT of channel c of `image` (minus `subtract` when given), row-major v * W + u, into
/// `out`: a 1-D FFT of every row, then of every column. Columns go through in blocks of kColumns adjacent
/// ones, gathered and scattered a row of the block at a time (whole cache lines instead of one value per
/// line); every FFT sees the same input as a column-by-column loop would give it, so the same bits.
void dft2(const Image& image, const Image* subtract, int c, std::vector<Complex>& out) {
  constexpr int kColumns = 8;
  const int w = image.width(), h = image.height();
  thread_local Eigen::FFT<double> fft;  // keeps its plans (twiddles) per length between calls
  thread_local std::vector<Complex> line, block, blockOut;
  out.resize(static_cast<size_t>(w) * h);
  line.resize(w), block.resize(static_cast<size_t>(kColumns) * h), blockOut.resize(static_cast<size_t>(kColumns) * h);
  const float* a = image.data();
  const float* b = subtract ? subtract->data() : nullptr;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = 3 * (static_cast<size_t>(y) * w + x) + c;
      line[x] = Complex(static_cast<double>(a[i]) - (b ? static_cast<double>(b[i]) : 0.0), 0.0);
    }
    fft.fwd(out.data() + static_cast<size_t>(y) * w, line.data(), w);
  }
  for (int u0 = 0; u0 < w; u0 += kColumns) {
    const int m = std::min(kColumns, w - u0);
    for (int y = 0; y < h; ++y)
      for (int k = 0; k < m; ++k) block[static_cast<size_t>(k) * h + y] = out[static_cast<size_t>(y) * w + u0 + k];
    for (int k = 0; k < m; ++k) fft.fwd(blockOut.data() + static_cast<size_t>(k) * h, block.data() + static_cast<size_t>(k) * h, h);
    for (int v = 0; v < h; ++v)
      for (int k = 0; k < m; ++k) out[static_cast<size_t>(v) * w + u0 + k] = blockOut[static_cast<size_t>(k) * h + v];
  }
}

int binOf(double rho) { return std::min(kSpectrumBins - 1, static_cast<int>(rho / kSpectrumBinWidth)); }

double blurGain(double rho) { return std::exp(-4 * kPi * kPi * kBlurSigma * kBlurSigma * rho * rho); }
}  // namespace

double frequencyRadius(int u, int v, int width, int height) {
  const double fu = (u < (width + 1) / 2 ? u : u - width) / static_cast<double>(width);
  const double fv = (v < (height + 1) / 2 ? v : v - height) / static_cast<double>(height);
  return std::hypot(fu, fv);
}

double RadialSpectrum::total() const {
  double t = 0;
  for (double e : energy) t += e;
  return t;
}

std::vector<double> powerSpectrum(const Image& image) {
  const size_t n = static_cast<size_t>(image.width()) * image.height();
  const double scale = 1.0 / (3.0 * static_cast<double>(n) * static_cast<double>(n));
  std::vector<double> p(n, 0.0);
  std::vector<Complex> e;
  for (int c = 0; c < 3; ++c) {
    dft2(image, nullptr, c, e);
    for (size_t i = 0; i < n; ++i) p[i] += std::norm(e[i]) * scale;
  }
  return p;
}

RadialSpectrum radialSpectrum(const Image& image) {
  RadialSpectrum r;
  const auto p = powerSpectrum(image);
  const int w = image.width(), h = image.height();
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) {
      const int b = binOf(frequencyRadius(u, v, w, h));
      r.energy[b] += p[static_cast<size_t>(v) * w + u], ++r.count[b];
    }
  return r;
}

SpectrumAccumulator::SpectrumAccumulator(const Image& reference)
    : reference_(reference), width_(reference.width()), height_(reference.height()) {
  const size_t n = static_cast<size_t>(width_) * height_;
  radius_.resize(n);
  for (int v = 0; v < height_; ++v)
    for (int u = 0; u < width_; ++u) radius_[static_cast<size_t>(v) * width_ + u] = frequencyRadius(u, v, width_, height_);
  gain_.resize(n);
  for (size_t i = 0; i < n; ++i) gain_[i] = blurGain(radius_[i]);
  sum_.assign(3 * n, Complex(0, 0));
  sumSquares_.assign(n, 0.0);
}

void SpectrumAccumulator::add(const Image& image) {
  if (image.width() != width_ || image.height() != height_)
    throw std::invalid_argument("SpectrumAccumulator::add: image size differs from the reference");
  const size_t n = static_cast<size_t>(width_) * height_;
  const double inv = 1.0 / static_cast<double>(n);
  double low = 0, total = 0, blurred = 0;
  thread_local std::vector<Complex> e;  // reused image after image
  for (int c = 0; c < 3; ++c) {
    dft2(image, &reference_, c, e);
    for (size_t i = 0; i < n; ++i) {
      const Complex z = e[i] * inv;  // P = |z|^2 / 3 for this channel
      const double p = std::norm(z) / 3.0;
      sum_[c * n + i] += z;
      sumSquares_[i] += p;
      total += p;
      if (radius_[i] < kLowFrequencyCutoff) low += p;
      blurred += p * gain_[i];
    }
  }
  lowFractions_.push_back(total > 0 ? low / total : 0.0);
  blurred_ += blurred;
  ++count_;
}

SpectrumMetrics SpectrumAccumulator::result() const {
  if (count_ < 2) throw std::logic_error("SpectrumAccumulator::result needs at least 2 images");
  SpectrumMetrics m;
  m.images = count_;
  const double k = count_;
  double mean = 0;
  for (double f : lowFractions_) mean += f / k;
  double var = 0;
  for (double f : lowFractions_) var += (f - mean) * (f - mean) / (k - 1);
  m.lowfreqError = mean, m.lowfreqErrorSe = std::sqrt(var / k);
  m.blurredMse = blurred_ / k;
  const size_t n = static_cast<size_t>(width_) * height_;
  for (size_t i = 0; i < n; ++i) {
    const int b = binOf(radius_[i]);
    // per channel sum_k |z_k - mean z|^2 = sum_k |z_k|^2 - |sum_k z_k|^2 / K; P takes the channel mean (/3)
    double spread = sumSquares_[i];
    for (int c = 0; c < 3; ++c) spread -= std::norm(sum_[c * n + i]) / 3.0 / k;
    m.error.energy[b] += sumSquares_[i] / k;
    m.noise.energy[b] += std::max(0.0, spread) / (k - 1);
    ++m.error.count[b], ++m.noise.count[b];
  }
  return m;
}

// ---------------------------------------------------------------------------
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
