#include "study/records/csv.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <tuple>

#include "core/error.h"
#include "core/files.h"
#include "core/format.h"
#include "core/gzip.h"
#include "study/study_scene.h"  // readFileBytes

namespace aliaslab {

namespace fs = std::filesystem;

namespace {
enum Col { kScene = 0, kWidth, kHeight, kSampler, kSpp, kFilter, kRadius, kParams, kRecon, kSeeds,
           kRefSpp = 15, kTarget = 24 };

// Per-seed values in one field: %.9g joined by ';' (no comma, so never quoted).
std::string joinReals(const std::vector<double>& values) {
  std::string out;
  for (double v : values) out += (out.empty() ? "" : ";") + formatReal(v);
  return out;
}

std::string quoted(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string joinKey(const std::vector<std::string>& f) {
  static const int cols[] = {kScene, kWidth, kHeight, kSampler, kSpp, kFilter, kRadius, kParams, kRecon, kSeeds, kRefSpp, kTarget};
  static const size_t prefilter = csvColumn("prefilter");
  std::string key;
  for (int c : cols) key += f[c] + '\x1f';
  key += f[prefilter] + '\x1f';
  if (f.size() > csvColumns().size())  // motion: frames, motion_dx, motion_dy
    for (size_t c = csvColumns().size(); c < csvColumns().size() + 3; ++c) key += f[c] + '\x1f';
  return key;
}

double num(const std::string& s) {
  try { return std::stod(s); } catch (const std::exception&) { return 0; }
}
}  // namespace

std::string formatCsvRow(const CsvRow& r) {
  std::ostringstream s;
  const auto real = [&s](double v) -> std::ostream& { return s << ',' << formatReal(v); };  // ",<v>"
  s << quoted(r.scene) << ',' << r.width << ',' << r.height << ',' << quoted(r.sampler) << ',' << r.spp << ','
    << quoted(r.filter);
  real(r.radius) << ',' << quoted(r.filterParams) << ',' << quoted(r.reconstruction) << ',' << r.seeds;
  real(r.mse), real(r.aliasing), real(r.noise), real(r.mseArea), real(r.psnr);
  s << ',' << r.refSpp;
  real(r.refError) << ',' << r.flagged << ',' << r.nanPixels << ',' << r.negativePixels << ',' << r.undefinedPixels;
  real(r.traceMs), real(r.reconstructMs);
  s << ',' << r.threads << ',' << quoted(r.target);
  real(r.mseTarget), real(r.blur), real(r.cross), real(r.mseSe), real(r.noiseSe), real(r.aliasingSe);
  real(r.mseTargetSe), real(r.lowfreqError), real(r.lowfreqErrorSe), real(r.blurredMse), real(r.meanSpp);
  s << ',' << r.maxSpp << ',' << quoted(r.prefilter);
  real(r.flip), real(r.targetRefError), real(r.blurSe);
  s << ',' << r.deterministic << ',' << joinReals(r.mseTargetSeeds);
  real(r.blurredMseOwn), real(r.lowfreqErrorOwn), real(r.lowfreqErrorOwnSe), real(r.cpuMs), real(r.cpuMsSe);
  for (size_t k = 0; k < r.blurRatio.size(); ++k) real(r.blurRatio[k]), real(r.blurRatioSe[k]);
  s << ',' << r.nonFiniteSamples;
  real(r.naturalRadius);
  if (const auto& a = r.align) {
    s << ',' << a->offsets;
    real(a->mseTarget), real(a->mseTargetSd), real(a->mseTargetSe);
    s << ',' << joinReals(a->perOffset);
  } else {
    s << ",,,,,";
  }
  if (const auto& m = r.motion) {
    s << ',' << m->frames;
    real(m->dx), real(m->dy), real(m->shimmer), real(m->shimmerSe), real(m->flickerSame), real(m->flickerSameSe);
    real(m->flickerNew), real(m->flickerNewSe), real(m->targetShimmer);
  }
  return s.str();
}

std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> fields(1);
  bool inQuotes = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (inQuotes) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') fields.back() += '"', ++i;
      else if (c == '"') inQuotes = false;
      else fields.back() += c;
    } else if (c == '"') {
      inQuotes = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

std::string csvKey(const std::vector<std::string>& fields) {
  if (!isStudyRow(fields)) return {};
  return joinKey(fields);
}

std::string csvKey(const CsvRow& row) { return csvKey(splitCsvLine(formatCsvRow(row))); }

std::vector<std::string> readCsvLines(const std::string& path, bool* motion) {
  const std::string text = readTextMaybeGzip(path, true);  // gzipped or not; a torn last gzip member dropped
  std::vector<std::string> lines;
  size_t start = 0;
  bool header = true;
  for (size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1) {
    const std::string line = text.substr(start, nl - start);
    if (header) {
      if (line != csvHeader() && line != csvHeader(true)) throw FileError(path, "not a study CSV (unexpected header)");
      if (motion) *motion = line == csvHeader(true);
      header = false;
    } else if (!line.empty()) {
      lines.push_back(line);
    }
  }
  if (header && !text.empty()) throw FileError(path, "not a study CSV (no complete header line)");
  return lines;  // a trailing partial line (no newline) is dropped
}

std::vector<std::string> sortCsvRows(std::vector<std::string> lines) {
  struct Item {
    std::vector<std::string> f;
    std::string line;
  };
  std::vector<Item> items;
  for (std::string& l : lines) items.push_back({splitCsvLine(l), std::move(l)});
  static const size_t kPrefilter = csvColumn("prefilter");
  auto order = [](const Item& a) {
    const auto& f = a.f;
    const size_t m = csvColumns().size();  // motion rows: frames, motion_dx, motion_dy last
    const bool moving = f.size() > m;
    return std::make_tuple(f[kScene], f[kSampler], num(f[kSpp]), f[kPrefilter], f[kFilter], num(f[kRadius]),
                           f[kRecon], num(f[kWidth]), num(f[kHeight]), num(f[kSeeds]), num(f[kRefSpp]), f[kParams],
                           f[kTarget], moving ? num(f[m]) : 1.0, moving ? num(f[m + 1]) : 0.0,
                           moving ? num(f[m + 2]) : 0.0);
  };
  std::erase_if(items, [](const Item& i) { return !isStudyRow(i.f); });
  std::stable_sort(items.begin(), items.end(), [&](const Item& a, const Item& b) { return order(a) < order(b); });
  std::vector<std::string> out;
  std::string previous;
  for (Item& i : items) {
    const std::string key = joinKey(i.f);
    if (!out.empty() && key == previous) continue;
    previous = key;
    out.push_back(std::move(i.line));
  }
  return out;
}

void writeCsvFile(const std::string& path, const std::vector<std::string>& lines, bool motion) {
  std::string text = csvHeader(motion) + '\n';
  for (const std::string& l : lines) text += l + '\n';
  writeTextMaybeGzip(path, text);  // gzipped when the name ends in .gz
}

void canonicaliseCsv(const std::string& path) {
  bool motion = false;
  std::vector<std::string> lines = readCsvLines(path, &motion);
  writeCsvFile(path, sortCsvRows(std::move(lines)), motion);
}

CsvAppender::CsvAppender(const std::string& path, bool motion) : path_(path) {
  std::error_code ec;
  requireRegularFile(path, "a study CSV is a regular file (it is read, resumed and appended to); give another "
                           "{csv} or {out}");
  bool exists = fs::exists(path, ec) && fs::file_size(path, ec) > 0;
  if (exists) {
    // Check that this is a study CSV before changing anything: a file that is not one is never modified.
    const std::string bytes = readFileBytes(path);
    gzip_ = isGzipPath(path) || isGzipData(bytes);
    std::string text = bytes;
    size_t wholeBytes = bytes.size();  // the bytes of the file's complete gzip members (all of a plain file)
    if (gzip_) {  // one gzip member per append: a killed run's torn last member is cut below, as a torn line is
      Gunzipped g = gunzipMembers(bytes);
      if (!g.damage.empty() && !g.cutShort)
        throw FileError(path, "not a gzipped study CSV (" + g.damage + "); left unchanged: give another {csv} or "
                              "{out}");
      text = std::move(g.text), wholeBytes = g.completeBytes;
    }
    const size_t first = text.find('\n');
    const std::string header = csvHeader(motion) + '\n';
    const bool studyHeader = first == std::string::npos ? header.compare(0, text.size(), text) == 0
                                                        : text.compare(0, first, csvHeader(motion)) == 0;
    const std::string firstLine = text.substr(0, first);
    if (!studyHeader && firstLine == csvHeader(!motion))
      throw FileError(path, std::string("holds a ") + (motion ? "still study (one frame)" : "study with frames") +
                                "; this run is " + (motion ? "one with frames" : "a still one") +
                                ", and one CSV holds one kind: left unchanged: give another {csv} or {out}");
    if (!studyHeader && csvHeader().compare(0, firstLine.size() + 1, firstLine + ",") == 0)
      throw FileError(path, "written by an older sweep (its header lacks the column(s) after '" +
                                firstLine.substr(firstLine.rfind(',') + 1) + "': " +
                                csvHeader().substr(firstLine.size() + 1) +
                                "); it cannot be resumed by this sweep and is left unchanged: give another {csv} or "
                                "{out} for a new study");
    if (!studyHeader)
      throw FileError(path, "not a study CSV (its first line is not the study header); left unchanged: give "
                            "another {csv} or {out}");
    const size_t nl = text.rfind('\n');
    const size_t keep = nl == std::string::npos ? 0 : nl + 1;
    // Every complete row must have the study's columns (a torn last line is a killed run's, and is cut).
    size_t start = first == std::string::npos ? text.size() : first + 1;
    for (int lineNo = 2; start < keep; ++lineNo) {
      const size_t end = text.find('\n', start);
      const std::string line = text.substr(start, end - start);
      const size_t n = splitCsvLine(line).size();
      const size_t expected = csvColumnCount(motion);
      if (!line.empty() && n != expected)
        throw ParseError(path, lineNo, "not a study row (" + std::to_string(n) + " fields, expected " +
                                           std::to_string(expected) + "); the CSV is left unchanged");
      start = end + 1;
    }
    // Resume: keep complete lines, cut a torn last line (or a torn header), and a gzip file's torn last member.
    if (gzip_ && keep != text.size() && keep > 0)  // a torn line inside whole members: rewrite the kept lines
      writeTextFile(path, gzipMember(text.substr(0, keep)));
    else if (const size_t size = gzip_ ? (keep > 0 ? wholeBytes : 0) : keep; size != bytes.size())
      fs::resize_file(path, size, ec);
    if (ec) throw FileError(path, "cannot truncate the partial last line: " + ec.message());
    exists = keep > 0;
    if (exists) {
      lines_ = readCsvLines(path);
      for (const std::string& l : lines_) keys_.insert(csvKey(splitCsvLine(l)));
    }
  }
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd_ < 0) throw FileError(path, "cannot open for appending: " + lastSystemError());
  if (!exists) {
    created_ = true;
    gzip_ = isGzipPath(path);
    const std::string h = gzip_ ? gzipMember(csvHeader(motion) + '\n') : csvHeader(motion) + '\n';
    if (const std::string why = writeFully(fd_, h); !why.empty()) throw FileError(path, "write failed: " + why);
  }
}

CsvAppender::~CsvAppender() {
  if (fd_ >= 0) ::close(fd_);
}

void CsvAppender::append(const CsvRow& row) { append(std::vector<CsvRow>{row}); }

void CsvAppender::append(const std::vector<CsvRow>& rows) {
  std::string lines;
  for (const CsvRow& row : rows) lines += formatCsvRow(row) + '\n';
  if (gzip_) lines = gzipMember(lines);  // one whole member per append
  if (const std::string why = writeFully(fd_, lines); !why.empty()) throw FileError(path_, "write failed: " + why);
  ::fdatasync(fd_);
  wrote_ = wrote_ || !rows.empty();
  for (const CsvRow& row : rows) keys_.insert(csvKey(row));
}

bool CsvAppender::discardIfUnused() {
  if (fd_ >= 0) ::close(fd_), fd_ = -1;
  std::error_code ec;
  return created_ && !wrote_ && fs::remove(path_, ec);
}

}  // namespace aliaslab
