// The study CSV: one row per (configuration, target), appended whole, resumable,
// shardable, mergeable.
//
// Columns (exact order; meanings in docs/science.md and the README):
//   scene,width,height,sampler,spp,filter,radius,filter_params,reconstruction,
//   seeds,mse,aliasing,noise,mse_area,psnr,ref_spp,ref_error,flagged,
//   nan_pixels,negative_pixels,undefined_pixels,trace_ms,reconstruct_ms,threads,
//   target,mse_target,blur,cross,mse_se,noise_se,aliasing_se,mse_target_se,
//   lowfreq_error,lowfreq_error_se,blurred_mse (measure/spectrum.h),
//   mean_spp,max_spp,prefilter,flip,
//   target_ref_error,blur_se,deterministic,mse_target_seeds,
//   blurred_mse_own,lowfreq_error_own,lowfreq_error_own_se,cpu_ms,cpu_ms_se,
//   blur_ratio_0.5,blur_ratio_0.5_se,blur_ratio_1,blur_ratio_1_se,blur_ratio_2,blur_ratio_2_se,
//   blur_ratio_4,blur_ratio_4_se,nonfinite_samples,
//   natural_radius,align_offsets,align_mse_target,align_mse_target_sd,align_mse_target_se,align_mse_target_offsets
// Against the configuration's own reference G (the same on every target row of a configuration): mse, aliasing,
// noise, psnr, ref_error (mean Var G), their *_se; mse_area against the pixel-area reference; blurred_mse_own,
// lowfreq_error_own(_se). Against the row's target T: mse_target, blur, cross, their *_se, target_ref_error
// (mean Var T), blurred_mse, lowfreq_error(_se), blur_ratio_S(_se) (the blur curve: the error's share left
// after a Gaussian blur of S pixels, measure/spectrum.h), flip, mse_target_seeds (the K per-seed mse_target values joined
// by ';', their mean is mse_target). Every mean square that holds a reference estimate has that reference's
// variance subtracted (measure/metrics.h), so an unbiased configuration has aliasing 0 within its *_se.
// flagged: 1 when mse_target < 2 mse_target_se (the error cannot be told from zero given the seeds' and the
// references' error; the analysis tells the two reasons apart, reference-limited or unstable: docs/science.md
// "Flagged rows"). deterministic: 1 when the K images were identical (the fixed grid: no standard error).
// (mean_spp, max_spp: samples per pixel actually spent, the mean over pixels
// and seeds and the largest in any pixel of any seed; both equal spp for a
// fixed sampler and differ for adaptive ones, render/adaptive.h.
// flip: mean LDR-FLIP of the K images against the row's target, measure/flip.h.
// cpu_ms: thread CPU milliseconds per image of the configuration's own work, the trace of its sample set plus
// its own reconstruction (its share of the shared splat pass), inner threads included, mean over the seeds;
// cpu_ms_se: their sd over the seeds / sqrt K. Unlike the wall times trace_ms and reconstruct_ms, a competing
// load does not inflate it; core/stopwatch.h CpuStopwatch.)
// nonfinite_samples: samples of the K images whose radiance was NaN or infinite and were left out of them (a light
// or colour beyond float range); 0 in a sound study, docs/integrity.md. An older CSV without the column cannot
// be resumed (CsvAppender names the missing columns); the analysis reads it as unknown.
// natural_radius: the registry's natural radius of the row's filter (filter/filter.h defaultFilterRadius: box 0.5,
// tent 1, gaussian 1.5, ...), so a row at radius == natural_radius is the filter at its own width.
// The fixed grid's alignment (study/sweep/alignment.h; docs/science.md "The grid and alignment"), on rows of the sampler
// uniform in a study with alignment offsets, empty on every other row: align_offsets K; align_mse_target the mean
// over the K seeded sub-pixel camera offsets of the grid's mse against the row's target rendered at that offset
// (that reference's variance subtracted); align_mse_target_sd the sd of the K values; align_mse_target_se
// sd / sqrt K (each offset has its own independent references, so their error is in the spread);
// align_mse_target_offsets the K values joined by ';' in offset order. The row's other columns stay those of the
// centred grid (offset 0).
// Motion (a study with frames F > 1, study/sweep/sweep_motion.h; docs/science.md "Motion"): the CSV gains, after every
// column above, csvMotionColumns(): frames,motion_dx,motion_dy (key columns), shimmer,shimmer_se,flicker_same,
// flicker_same_se,flicker_new,flicker_new_se of the configuration's frames registered to the content (no target
// enters: the same on every target row), and target_shimmer, the row's target's own registered shimmer (the
// pixel-area image aliases too; measure/motion.h). The still columns above are
// then those of frame 0. A still study (F = 1) writes exactly the columns above; one CSV holds one kind.
// Reals are printed with %.9g; fields holding a comma or quote are quoted.
//
// A row's key is its identifying columns (scene ... reconstruction, seeds,
// ref_spp, target, prefilter; with motion also frames, motion_dx, motion_dy): a rerun skips configurations whose
// rows (one per target) are all in the file.
// CsvAppender opens an existing file for resumption: it checks the header and rows first (a file that is
// not a study CSV is never modified),
// truncates a trailing partial line (a killed run), and appends each new row
// with one write() followed by fsync, so a finished row is never lost or torn.
// A CSV named *.gz is gzipped (core/gzip.h): every append is one whole gzip member written with one write(),
// so a killed run's torn last member is cut on resume as a torn line is; readers take either kind, told by
// the gzip magic, and the end of a run or a merge writes the whole file as one member.
// sortCsvRows() puts rows into the canonical order (by key, numbers compared
// as numbers), which the end of a run and the merge of shards (study/records/merge.h) both apply, so a
// resumed, sharded or interrupted run ends with the same file.
#pragma once
#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace aliaslab {

/// The motion columns of a row (studies with F > 1 frames).
struct MotionColumns {
  int frames = 0;
  double dx = 0, dy = 0;  ///< camera motion in pixels per frame
  double shimmer = 0, shimmerSe = 0, flickerSame = 0, flickerSameSe = 0, flickerNew = 0, flickerNewSe = 0;
  double targetShimmer = 0;  ///< the target's own registered shimmer
};

/// The fixed grid's alignment columns of a row (study/sweep/alignment.h).
struct AlignColumns {
  int offsets = 0;                   ///< K
  double mseTarget = 0, mseTargetSd = 0, mseTargetSe = 0;
  std::vector<double> perOffset;     ///< per offset k: the grid's corrected mse against T at offset k
};

struct CsvRow {
  std::string scene;
  int width = 0, height = 0;
  std::string sampler;
  int spp = 0;
  std::string filter;
  double radius = 0;
  std::string filterParams;
  std::string reconstruction;
  int seeds = 0;
  double mse = 0, aliasing = 0, noise = 0, mseArea = 0, psnr = 0;
  int refSpp = 0;
  double refError = 0;
  int flagged = 0;
  long long nanPixels = 0, negativePixels = 0, undefinedPixels = 0;
  double traceMs = 0, reconstructMs = 0;
  double flip = 0;
  int threads = 0;
  std::string target;  ///< the row's target T as "filter:radius" ("box:0.5" is the pixel area)
  double mseTarget = 0, blur = 0, cross = 0;
  double mseSe = 0, noiseSe = 0, aliasingSe = 0, mseTargetSe = 0;
  double lowfreqError = 0, lowfreqErrorSe = 0, blurredMse = 0;  ///< measure/spectrum.h
  double meanSpp = 0;  ///< mean samples per pixel actually spent (over pixels and seeds)
  int maxSpp = 0;      ///< most samples in one pixel (over seeds)
  std::string prefilter = "none";  ///< none | footprint (texture pre-filtering, docs/prefiltering.md)
  double targetRefError = 0;       ///< mean Var T: the target's own error (subtracted from mse_target)
  double blurSe = 0;               ///< standard error of blur (the references' error)
  int deterministic = 0;           ///< 1 when the K images were identical bit for bit
  std::vector<double> mseTargetSeeds;  ///< per seed k: corrected mse_target of image k (mean = mseTarget)
  double blurredMseOwn = 0, lowfreqErrorOwn = 0, lowfreqErrorOwnSe = 0;  ///< against the own reference G
  double cpuMs = 0, cpuMsSe = 0;   ///< thread CPU ms per image (mean over seeds) and its standard error
  std::array<double, 4> blurRatio{}, blurRatioSe{};  ///< the blur curve at sigma 0.5, 1, 2, 4 (measure/spectrum.h)
  long long nonFiniteSamples = 0;  ///< NaN / infinite samples left out of the K images (summed over seeds)
  double naturalRadius = 0;        ///< the registry's natural radius of the row's filter
  std::optional<AlignColumns> align;  ///< rows of the fixed grid in a study with alignment offsets; else empty cells
  std::optional<MotionColumns> motion;  ///< set in a study with frames (F > 1): the motion columns follow
};

/// The header line (no newline); with `motion`, the motion columns after the still ones.
const std::string& csvHeader(bool motion = false);
/// Column names in order (the still study's).
const std::vector<std::string>& csvColumns();
/// The motion columns, which follow csvColumns() in a study with frames.
const std::vector<std::string>& csvMotionColumns();
/// Whether `fields` is a study row: the still columns, or the still and the motion columns.
bool isStudyRow(const std::vector<std::string>& fields);
/// The number of fields in a row: the still columns, plus the motion columns in a study with frames.
inline size_t csvColumnCount(bool motion) {
  return csvColumns().size() + (motion ? csvMotionColumns().size() : 0);
}
/// Index of the column `name` in csvColumns(); throws std::out_of_range when there is none.
size_t csvColumn(const std::string& name);
/// Indices of the timing columns (trace_ms, reconstruct_ms, cpu_ms, cpu_ms_se), which may differ between runs.
std::vector<size_t> csvTimingColumns();

/// One formatted line (no newline).
std::string formatCsvRow(const CsvRow& row);
/// The key of a row: its identifying fields as they are printed.
std::string csvKey(const CsvRow& row);

/// Splits one CSV line into fields (RFC 4180 quoting).
std::vector<std::string> splitCsvLine(const std::string& line);
/// Key of a parsed line (same text as csvKey of the row it came from).
std::string csvKey(const std::vector<std::string>& fields);

/// Appends rows to a CSV, resuming an existing one.
class CsvAppender {
 public:
  /// Opens (creating with the header if missing or empty). Throws FileError
  /// when the file cannot be opened or has another header.
  /// `motion`: the study has frames (the motion header); a file with the other header is refused.
  explicit CsvAppender(const std::string& path, bool motion = false);
  ~CsvAppender();
  CsvAppender(const CsvAppender&) = delete;
  CsvAppender& operator=(const CsvAppender&) = delete;

  bool has(const std::string& key) const { return keys_.count(key) > 0; }
  /// Treats the row `key` as missing (it is measured and appended again; canonical order keeps one copy): the
  /// sweep's resume for a configuration whose spectra were lost (study/records/spectrum_files.h completeSpectra).
  void forget(const std::string& key) { keys_.erase(key); }
  /// The rows the file held when it was opened.
  const std::vector<std::string>& resumedLines() const { return lines_; }
  /// Writes the row with one write() and fsync. Throws FileError.
  void append(const CsvRow& row);
  /// Writes several rows with one write() and one fsync (a torn tail is cut on resume). Throws FileError.
  void append(const std::vector<CsvRow>& rows);
  /// After a refusal: removes the file when this appender created it and no row was ever written to it (a
  /// header-only CSV would look like a study); returns whether it did. The appender is closed either way.
  bool discardIfUnused();

 private:
  std::string path_;
  int fd_ = -1;
  bool created_ = false;  ///< the file was created (or was empty) here
  bool wrote_ = false;    ///< a row was appended
  bool gzip_ = false;     ///< the file is gzipped (named *.gz, or found so): each append writes one gzip member
  std::set<std::string> keys_;
  std::vector<std::string> lines_;
};

/// Reads a CSV's data lines (header checked, partial last line dropped); `motion` (if given) tells which header.
std::vector<std::string> readCsvLines(const std::string& path, bool* motion = nullptr);

/// Sorts lines into canonical order and drops exact-key duplicates (first kept).
std::vector<std::string> sortCsvRows(std::vector<std::string> lines);

/// Writes header + lines to `path` atomically (temporary file, then rename).
void writeCsvFile(const std::string& path, const std::vector<std::string>& lines, bool motion = false);

/// Rewrites a CSV in canonical order.
void canonicaliseCsv(const std::string& path);


}  // namespace aliaslab
