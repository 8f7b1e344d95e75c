// The fixed grid judged over alignments (docs/science.md "The grid and alignment"): the grid's error depends on
// where the scene's features fall relative to the pixels, so it is measured by moving the camera, not the points.
//
// Protocol, per scene of a study with StudyConfig::alignOffsets = K > 0 and rows of the sampler `uniform`:
// alignmentReferences() gives, for each offset k = 0 .. K-1, the references of the study's targets rendered with
// the camera's film shifted by alignmentOffset(k) (the references move with the scene), each cached under its own
// key (FilmOffsetCamera: the content hash gains the offset; the cache manifest records it as "film_offset"). Per
// group of the fixed grid, after its K seeds (whose rows stay those of the centred grid, offset 0),
// measureGroupAlignment() traces the grid once per offset with the same film shift, reconstructs it with every
// row's filter and mode (film/film.h; importance rows trace their own), and gives each row, per target T, the K
// values e_k = mean (I_k - T_k)^2 - mean D_k^2 (T_k the target at offset k, D_k its half-difference: its
// variance subtracted, as everywhere) and their mean, sd and sd / sqrt K (PendingRow::align; CSV columns
// align_*, study/records/csv.h). Each offset's references are independent of every other's, so the spread of the e_k
// holds their error: sd / sqrt K is the whole standard error.
//
// The offset is a shift of the film position of every camera ray (scene/camera.h makeShiftedCamera): the image
// at offset o at film position p is what film position p + o showed at offset 0, an image translation for the
// orthographic camera and a film-plane (lens) shift for the perspective one; it composes with every sampler,
// filter and reconstruction because all of them reach the scene through the camera. Offsets derive from k by a
// hash, uniform over one pixel; no number depends on the thread count.
#pragma once
#include <memory>
#include <vector>

#include "core/math.h"
#include "render/tracer.h"
#include "study/config.h"
#include "study/reference/reference.h"
#include "study/study_scene.h"
#include "study/sweep/sweep_rows.h"

namespace aliaslab {

/// The sampler whose rows get the alignment columns: the fixed grid.
inline constexpr const char* kFixedGridSampler = "uniform";

/// The film offset of alignment offset k in pixels: (u - 1/2, v - 1/2), u and v uniform in [0, 1) from a hash of
/// k (the same for every scene and study).
Vec2 alignmentOffset(int k);

/// Points a scene's camera at a film offset while it lives (the camera and content hash restored after).
class FilmOffsetCamera {
 public:
  explicit FilmOffsetCamera(StudyScene& scene);
  ~FilmOffsetCamera();
  FilmOffsetCamera(const FilmOffsetCamera&) = delete;
  FilmOffsetCamera& operator=(const FilmOffsetCamera&) = delete;
  /// Film position p now sees what p + offset (pixels) saw; the content hash (the references' cache key) gains
  /// the offset's exact bits, and scene.filmOffset records it. Offset zero is the scene as written.
  void set(const Vec2& offset);

 private:
  StudyScene& s_;
  std::unique_ptr<Camera> base_;
  uint64_t hash_;
};

/// The references of `targets` at each of the config's alignOffsets offsets (element k = offset k), from the cache
/// or rendered with `options` (their spp: config.alignRefSpp).
std::vector<ReferenceSet> alignmentReferences(const StudyConfig& config, StudyScene& scene,
                                              const std::vector<StudyFilter>& targets, const ReferenceOptions& options);

/// The reference options of the offset references: the study's, at alignRefSpp samples per pixel.
ReferenceOptions alignmentReferenceOptions(const StudyConfig& config);

/// The alignment columns of every row of a fixed-grid group (rows traced with `tracer`, which reads `scene`'s
/// camera); `refs[k].images[j]` is target j at offset k.
void measureGroupAlignment(StudyScene& scene, const Tracer& tracer,
                           const SampleSetGroup& group, std::vector<PendingRow>& rows,
                           const std::vector<ReferenceSet>& refs, int threads);

}  // namespace aliaslab
