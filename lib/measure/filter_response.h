// Each filter's 1-D profile and frequency response, as CSV rows (the
// filterprofile program; analysis charts/filter_profiles.py draws them). One source
// of truth: the library's Filter::profile and Filter::eval.
//
// Columns: filter,radius,describe,kind,x,value
//   kind = profile:  x = offset in pixels in [-r - 0.25, r + 0.25], value = the
//     1-D profile g(x) (Filter::profile; f(x, y) = g(x) g(y) for separable
//     filters, g(|d|) for radial)
//   kind = response: x = frequency in cycles per pixel in [0, maxFrequency],
//     value = |H(x)|, the 2-D filter's normalised Fourier transform along the
//     x axis, H(nu) = int int f(x, y) exp(-2 pi i nu x) dx dy / int int f dx dy,
//     computed as the cosine transform of the projection p(x) = int f(x, y) dy
//     (midpoint rule, step r / 256 in x and y). For separable filters this is
//     the 1-D transform of the profile; for radial ones (tent, gaussian) it is
//     the true response of the disc-supported filter, not of its slice.
#pragma once
#include <ostream>
#include <string>

#include "filter/filter.h"

namespace aliaslab {

struct FilterResponseGrid {
  double maxFrequency = 2.0;  ///< cycles per pixel
  int frequencySteps = 400;   ///< response samples in [0, maxFrequency]
  int profileSteps = 400;     ///< profile samples across [-r - 0.25, r + 0.25]
};

/// The CSV header line (with its newline).
std::string filterResponseCsvHeader();

/// Writes the profile rows, then the response rows, of `f` to `os`.
void writeFilterResponseCsv(std::ostream& os, const Filter& f, const FilterResponseGrid& grid);

}  // namespace aliaslab
