// The study CSV's columns (study/records/csv.h): their names and order, the header line, and where a column sits.
#include <algorithm>
#include <stdexcept>

#include "study/records/csv.h"

namespace aliaslab {

const std::vector<std::string>& csvColumns() {
  static const std::vector<std::string> cols = {
      "scene", "width", "height", "sampler", "spp", "filter", "radius", "filter_params",
      "reconstruction", "seeds", "mse", "aliasing", "noise", "mse_area", "psnr", "ref_spp",
      "ref_error", "flagged", "nan_pixels", "negative_pixels", "undefined_pixels", "trace_ms",
      "reconstruct_ms", "threads", "target", "mse_target", "blur", "cross", "mse_se", "noise_se",
      "aliasing_se", "mse_target_se", "lowfreq_error", "lowfreq_error_se", "blurred_mse", "mean_spp", "max_spp",
      "prefilter", "flip", "target_ref_error", "blur_se", "deterministic", "mse_target_seeds", "blurred_mse_own",
      "lowfreq_error_own", "lowfreq_error_own_se", "cpu_ms", "cpu_ms_se", "blur_ratio_0.5", "blur_ratio_0.5_se",
      "blur_ratio_1", "blur_ratio_1_se", "blur_ratio_2", "blur_ratio_2_se", "blur_ratio_4", "blur_ratio_4_se",
      "nonfinite_samples", "natural_radius", "align_offsets", "align_mse_target", "align_mse_target_sd",
      "align_mse_target_se", "align_mse_target_offsets"};
  return cols;
}

const std::vector<std::string>& csvMotionColumns() {
  static const std::vector<std::string> cols = {
      "frames", "motion_dx", "motion_dy", "shimmer", "shimmer_se", "flicker_same", "flicker_same_se", "flicker_new",
      "flicker_new_se", "target_shimmer"};
  return cols;
}

const std::string& csvHeader(bool motion) {
  static const std::string still = [] {
    std::string h;
    for (const std::string& c : csvColumns()) h += (h.empty() ? "" : ",") + c;
    return h;
  }();
  static const std::string moving = [] {
    std::string h = still;
    for (const std::string& c : csvMotionColumns()) h += "," + c;
    return h;
  }();
  return motion ? moving : still;
}

bool isStudyRow(const std::vector<std::string>& f) {
  return f.size() == csvColumnCount(false) || f.size() == csvColumnCount(true);
}

size_t csvColumn(const std::string& name) {
  const auto& cols = csvColumns();
  const auto it = std::find(cols.begin(), cols.end(), name);
  if (it == cols.end()) throw std::out_of_range("no CSV column '" + name + "'");
  return static_cast<size_t>(it - cols.begin());
}

std::vector<size_t> csvTimingColumns() {
  return {csvColumn("trace_ms"), csvColumn("reconstruct_ms"), csvColumn("cpu_ms"), csvColumn("cpu_ms_se")};
}

}  // namespace aliaslab
