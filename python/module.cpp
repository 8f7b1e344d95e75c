// import aliaslab: samplers and filters as numpy arrays (this file), renders and references
// (render_bindings.cpp). docs/python.md lists every function; bindings.h says how errors are raised.
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.h"
#include "core/error.h"
#include "filter/filter.h"
#include "render/sample_source.h"
#include "sampling/sampler.h"

namespace aliaslab::python {
namespace {

/// points() refuses counts above this (16M points, 128 MB as float64), as a ValueError naming spp.
constexpr int kMaxPoints = 1 << 24;

py::array_t<double> points(const std::string& sampler, int spp, std::pair<int, int> pixel, uint64_t seed) {
  if (spp > kMaxPoints) throw OptionError("spp", "at most " + std::to_string(kMaxPoints) + " points, found " +
                                                     std::to_string(spp));
  const std::unique_ptr<Sampler> s = makeSampler(sampler, spp, seed);  // OptionError "sampler" / "spp"
  std::vector<Vec2> u(spp);
  s->generate(pixel.first, pixel.second, u.data());  // as traceSamples does for pixel (px, py)
  py::array_t<double> out({static_cast<py::ssize_t>(spp), py::ssize_t(2)});
  auto a = out.mutable_unchecked<2>();
  for (int k = 0; k < spp; ++k) a(k, 0) = u[k].x(), a(k, 1) = u[k].y();  // floats, exact as float64
  return out;
}

/// The filter of (name, radius, params); radius None: the filter's natural radius (defaultFilterRadius).
std::unique_ptr<Filter> filterOf(const std::string& name, const py::object& radius, const FilterParams& params) {
  const double r = radius.is_none() ? defaultFilterRadius(name, params) : radius.cast<double>();
  if (!std::isfinite(r)) throw OptionError("radius", "must be a finite number of pixels, found " + std::to_string(r));
  return makeFilter(name, static_cast<float>(r), params);  // OptionError "filter" / "radius" / "filter-param"
}

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

}  // namespace
}  // namespace aliaslab::python

PYBIND11_MODULE(aliaslab, m) {
  using namespace aliaslab;
  using namespace aliaslab::python;
  m.doc() = "aliaslab from Python: samplers, filters, renders and references as numpy arrays (docs/python.md)";

  m.def(
      "samplers",
      [](bool adaptive) { return adaptive ? sampleSourceNames() : allSamplerNames(); }, py::arg("adaptive") = false,
      "Every sampler name points() takes (plain and WRAPPER:BASE); adaptive=True adds the adaptive methods "
      "render() also takes.");
  m.def(
      "points",
      [](const std::string& sampler, int spp, std::pair<int, int> pixel, uint64_t seed) {
        return guarded([&] { return py::object(points(sampler, spp, pixel, seed)); });
      },
      py::arg("sampler"), py::arg("spp"), py::arg("pixel") = std::pair<int, int>{0, 0}, py::arg("seed") = 0,
      "The spp sample positions in [0,1)^2 of pixel (px, py) as an (spp, 2) float64 array: the floats the "
      "renderer traces at film position (px + u, py + v). Film y points up: pixel row py is row H - 1 - py of "
      "render()'s array.");
  m.def("filters", [](bool all) { return all ? allFilterNames() : filterNames(); }, py::arg("all") = false,
        "The study's filter names; all=True adds gaussian-cut and the course variants.");
  m.def(
      "default_radius",
      [](const std::string& name, const FilterParams& params) {
        return guarded([&] { return py::cast(defaultFilterRadius(name, params)); });
      },
      py::arg("name"), py::arg("params") = FilterParams{},
      "The filter's natural radius in pixels (used when radius is None).");
  m.def(
      "filter_eval",
      [](const std::string& name, const py::object& radius, const FloatArray& x, const FloatArray& y,
         const FilterParams& params) {
        return guarded([&] {
          const std::unique_ptr<Filter> f = filterOf(name, radius, params);
          auto eval = py::vectorize([&f](float dx, float dy) { return f->eval(dx, dy); });
          return py::object(eval(x, y));
        });
      },
      py::arg("name"), py::arg("radius"), py::arg("x"), py::arg("y"), py::arg("params") = FilterParams{},
      "The filter's weight f(x, y) at offsets (x, y) in pixels from a pixel centre, as float32, broadcast over "
      "numpy arrays (Filter::eval; radius None: the natural radius).");
  m.def(
      "filter_profile",
      [](const std::string& name, const py::object& radius, const FloatArray& x, const FilterParams& params) {
        return guarded([&] {
          const std::unique_ptr<Filter> f = filterOf(name, radius, params);
          auto profile = py::vectorize([&f](float t) { return f->profile(t); });
          return py::object(profile(x));
        });
      },
      py::arg("name"), py::arg("radius"), py::arg("x"), py::arg("params") = FilterParams{},
      "The filter's 1-D profile g(x) (Filter::profile), as the filterprofile program prints it.");
  m.def(
      "filter_describe",
      [](const std::string& name, const py::object& radius, const FilterParams& params) {
        return guarded([&] { return py::cast(filterOf(name, radius, params)->describe()); });
      },
      py::arg("name"), py::arg("radius") = py::none(), py::arg("params") = FilterParams{},
      "One line naming the filter, its radius and shape parameters, as in the study's CSV.");
  bindRender(m);
}
