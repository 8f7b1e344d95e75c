// The aliaslab Python module (python/): what its files share.
//
// The module is a thin layer over lib/, like the experiments: each function
// checks its arguments, calls the library's own entry point and converts the
// result to numpy. Every library exception is caught at the boundary
// (guarded()) and raised as a Python exception whose message names the
// argument in Python's terms: OptionError (a bad argument) and ParseError
// (a bad scene) as ValueError, a missing file as FileNotFoundError, other
// file errors as OSError, a Python value of the wrong type as TypeError,
// std::bad_alloc as MemoryError, anything else as RuntimeError. Nothing
// escapes as a C++ exception, so the interpreter survives every bad call.
#pragma once
#include <functional>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "core/image.h"

namespace aliaslab::python {

namespace py = pybind11;

/// Runs `body`; a library exception becomes the Python exception described above.
py::object guarded(const std::function<py::object()>& body);

/// Raises FileNotFoundError "<argument>: '<path>' not found" unless `path` is a regular file.
void requireFile(const std::string& path, const std::string& argument);

/// The image as a new (height, width, 3) float32 array, row 0 at the top: the floats the EXR writer stores, in
/// its order (the library's images keep row 0 at the bottom, film y pointing up).
py::array_t<float> imageArray(const Image& image);

/// Registers render() and reference() (render_bindings.cpp).
void bindRender(py::module_& m);

}  // namespace aliaslab::python
