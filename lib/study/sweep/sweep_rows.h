// The rows of the sweep: a configuration from its template (identifying columns) to its CSV line.
//
// A configuration has one CSV row per target of the study (the target column is part of the key); it is measured
// once for all targets. Protocol, per group of one scene: planRows lists the configurations with a target row
// still missing from the CSV (resume; a configuration is done only when all its target rows are there), each
// with the configuration's filter (built once by expandStudy), and collects the (filter, radius) references they
// need; each configuration then gets its reference and its RowMeasure against every target (study/sweep/sweep_scene.h
// startRows); the group's seeds are folded into them (study/sweep/sweep_group.h); finishRow turns a configuration's
// sums into its missing target rows, spectra and images (one task per configuration, each writing only its own
// files); writeRows writes the group's spectra and CSV lines in order, on the writer's thread
// (study/sweep/group_writer.h).
#pragma once
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "core/image.h"
#include "study/config.h"
#include "study/records/csv.h"
#include "measure/flip/flip.h"
#include "measure/spectrum.h"
#include "study/sweep/row_measure.h"
#include "study/study_scene.h"

namespace aliaslab {

/// One configuration in flight: its rows' identifying columns, filter, reference and running measures.
struct PendingRow {
  CsvRow row;                                  ///< the identifying columns, target not set
  std::vector<bool> missing;                   ///< per target of the study: its row is not in the CSV yet
  ReconMode mode = ReconMode::WeightedAverage;
  StudyFilter filter;                          ///< the configuration's (filter, radius), built once
  const ReferenceImage* reference = nullptr;   ///< set by startRows
  std::unique_ptr<RowMeasure> measure;         ///< against G and every target (then the area if not a target)
  ReconStats stats;
  double traceMs = 0, reconMs = 0;
  std::vector<double> cpuMs;  ///< per seed, in seed order: CPU ms of its trace + this row's reconstruction
  Image seed0;
  std::vector<const FlipReference*> flipTargets;  ///< per target: what its flip column compares against
  std::vector<double> flipSums;  ///< per target: sum over the seeds of meanFlip(I_k, T), in seed order
  std::vector<CsvRow> rows;      ///< finishRow: the missing target rows, in target order
  std::vector<MotionColumns> motion;  ///< per target: the motion columns (frames > 1, study/sweep/sweep_motion.h)
  std::vector<AlignColumns> align;    ///< per target: the fixed grid's alignment columns (study/sweep/alignment.h)
  std::vector<Image> frame0;  ///< frames > 1: each seed's still image (frame 0), in seed order, for the motion pass
};

/// What an adaptive sampler actually spent in a group (mean over seeds of the mean spp, max over seeds),
/// folded in seed order; a fixed-count sampler spends exactly its spp.
struct GroupSpent {
  double meanSpp;
  int maxSpp;
  Image density0;  ///< seed 0's samples per pixel (adaptive samplers, images on)
};

/// Resume: the configurations of `groups` (one scene, named `stem` and rendered at `size`) with a target row still
/// missing from the CSV `out` (all of them when there is none), one list per group; adds the (filter, radius) of
/// each to `specs` (the references to render) and counts the rows already present in `skipped`.
std::vector<std::vector<PendingRow>> planRows(const StudyConfig& config, const std::vector<Target>& targets,
                                              const std::string& stem,
                                              SceneSize size, const std::vector<const SampleSetGroup*>& groups,
                                              const CsvAppender* out, std::vector<StudyFilter>& specs, size_t& skipped);

/// "Configuration finished": its measures into its missing target rows (p.rows; `targets` the study's, whose
/// measures come first in p.measure's result, `areaIndex` the pixel area's position there), its spectra into
/// `spectrum`, and (images on) its images into `imageDir`; the accumulators and images are released.
void finishRow(PendingRow& p, const std::vector<Target>& targets, size_t areaIndex,
               const std::filesystem::path& imageDir, bool images, const GroupSpent& spent, int seeds, SpectrumMetrics& spectrum);

/// A finished group's configurations, in order (`rows[i]` the target rows of configuration i, `spectra[i]` its
/// spectra): spectra first (a row in the study CSV always has its spectra; a repeat is dropped at the end), then
/// the CSV rows, each file with one write (the CSV with one fsync). Touches only the files, `out` and
/// `spectraWritten` (the spectrum CSVs to put in canonical order at the end).
void writeRows(const StudyConfig& config, const std::vector<std::vector<CsvRow>>& rows,
               const std::vector<SpectrumMetrics>& spectra, CsvAppender& out, std::set<std::string>& spectraWritten);

}  // namespace aliaslab
