// A study's frames (study/sweep/motion_frame.h).
#include "study/sweep/motion_frame.h"

#include <cmath>
#include <cstdio>

#include "core/error.h"

namespace aliaslab {

void setMotionFrame(StudyScene& s, const Camera& base, uint64_t baseHash, int t, double dx, double dy) {
  const Vec2 offset = frameScreenOffset(t, dx, dy, s.width, s.height);
  s.scene.camera = makeShiftedCamera(base, offset);
  char exact[96];  // %a: every bit of the offset, so no two offsets share a key
  std::snprintf(exact, sizeof exact, "motion offset %a %a", double(offset.x()), double(offset.y()));
  s.contentHash = offset.isZero(0.f) ? baseHash : hashBytes(exact, baseHash);
}

std::pair<double, double> parseMotion(const std::string& text) {
  const size_t comma = text.find(',');
  double v[2] = {NAN, NAN};
  if (comma != std::string::npos && text.find(',', comma + 1) == std::string::npos) {
    const std::string parts[2] = {text.substr(0, comma), text.substr(comma + 1)};
    for (int i = 0; i < 2; ++i) try {
        size_t used = 0;
        v[i] = std::stod(parts[i], &used);
        if (used != parts[i].size() || parts[i].empty()) v[i] = NAN;
      } catch (const std::exception&) {
      }
  }
  if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || std::abs(v[0]) > 1e4 || std::abs(v[1]) > 1e4)
    throw OptionError("motion", "expected dx,dy: two finite numbers of pixels per frame (at most 1e4), e.g. "
                                "0.25,0; found '" + text + "'");
  return {v[0], v[1]};
}

}  // namespace aliaslab
