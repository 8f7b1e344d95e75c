// The rows of the sweep: a configuration from its template (identifying columns) to its CSV line.
//
// Protocol, per group of one scene: planRows lists the rows still missing from the CSV (resume), each with the
// configuration's filter (built once by expandStudy), and collects the (filter, radius) references they need;
// each row then gets its reference and accumulators (study/sweep_scene.h startRows); the group's seeds are
// folded into them (study/sweep_group.h); finishRow turns a row's sums into its numbers, spectra and images (one
// task per row, each writing only its own files); writeRows writes the group's spectra and CSV lines in row
// order, on the writer's thread (study/group_writer.h).
#pragma once
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/image.h"
#include "study/config.h"
#include "study/csv.h"
#include "measure/flip.h"
#include "measure/metrics.h"
#include "measure/spectrum.h"
#include "study/study_scene.h"

namespace aliaslab {

/// One configuration (row) in flight: its row, filter, reference and running metrics.
struct PendingRow {
  CsvRow row;
  ReconMode mode = ReconMode::WeightedAverage;
  StudyFilter filter;                          ///< the configuration's (filter, radius), built once
  const ReferenceImage* reference = nullptr;   ///< set by startRows
  std::unique_ptr<MetricAccumulator> metrics;
  std::unique_ptr<SpectrumAccumulator> spectrum;
  ReconStats stats;
  double traceMs = 0, reconMs = 0;
  std::vector<double> cpuMs;  ///< per seed, in seed order: CPU ms of its trace + this row's reconstruction
  Image seed0;
  const FlipReference* flipTarget = nullptr;  ///< what the flip column compares against (the study's target)
  double flipSum = 0;                         ///< sum over the seeds of meanFlip(I_k, target), in seed order
};

/// What an adaptive sampler actually spent in a group (mean over seeds of the mean spp, max over seeds),
/// folded in seed order; a fixed-count sampler spends exactly its spp.
struct GroupSpent {
  double meanSpp;
  int maxSpp;
  Image density0;  ///< seed 0's samples per pixel (adaptive samplers, images on)
};

/// The (filter, radius) of the pixel-area reference (box, r = 0.5).
inline const FilterSpec kAreaSpec{"box", 0.5};

/// Resume: the rows of `groups` (one scene, named `stem` and rendered at `size`) still missing from the CSV `out`
/// (all of them when there is none), one list per group; adds the (filter, radius) of each to `specs` (the
/// references to render) and counts the rows present in `skipped`.
std::vector<std::vector<PendingRow>> planRows(const StudyConfig& config, const Target& target, const std::string& stem,
                                              SceneSize size, const std::vector<const SampleSetGroup*>& groups,
                                              const CsvAppender* out, std::vector<FilterSpec>& specs, size_t& skipped);

/// "Row finished": the row's metrics into its CSV row, its spectra into `spectrum`, and (images on) its images
/// into `imageDir`; the row's accumulators and images are released.
void finishRow(PendingRow& p, const std::filesystem::path& imageDir, bool images, const GroupSpent& spent, int seeds,
               SpectrumMetrics& spectrum);

/// A finished group's rows, in row order: spectra first (a row in the study CSV always has its spectra; a repeat
/// is dropped at the end), then the CSV rows, each file with one write (the CSV with one fsync). Touches only the
/// files, `out` and `spectraWritten` (the spectrum CSVs to put in canonical order at the end).
void writeRows(const StudyConfig& config, const std::vector<CsvRow>& rows, const std::vector<SpectrumMetrics>& spectra,
               CsvAppender& out, std::set<std::string>& spectraWritten);

}  // namespace aliaslab
