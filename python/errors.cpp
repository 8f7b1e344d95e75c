// Library exceptions -> Python exceptions (bindings.h), and the image conversion.
#include <cstring>
#include <filesystem>
#include <new>

#include "bindings.h"
#include "common/front_end.h"
#include "core/error.h"

namespace aliaslab::python {
namespace {

// The library's parameter keys in this module's argument names (experiments/common/front_end.h: the one place a
// front end maps keys); keys that already are argument names ("sampler", "spp", "filter", "radius", "size",
// "seed", "threads") are printed as they are.
const FrontEnd kPython{"aliaslab",
                       {{"filter-param", "params"}, {"ref-spp", "spp"}, {"ref-batch", "batch"},
                        {"ref-sampler", "sampler"}}};

[[noreturn]] void raise(PyObject* type, const std::string& message) {
  PyErr_SetString(type, message.c_str());
  throw py::error_already_set();
}

}  // namespace

py::object guarded(const std::function<py::object()>& body) {
  try {
    return body();
  } catch (const py::error_already_set&) {
    throw;  // already a Python exception
  } catch (const OptionError& e) {
    raise(PyExc_ValueError, kPython.message(e));
  } catch (const ParseError& e) {
    raise(PyExc_ValueError, e.what());
  } catch (const FileError& e) {
    raise(PyExc_OSError, e.what());
  } catch (const InputError& e) {
    raise(PyExc_ValueError, kPython.message(e));
  } catch (const py::cast_error& e) {
    raise(PyExc_TypeError, std::string("an argument of the wrong type: ") + e.what());
  } catch (const std::bad_alloc&) {
    raise(PyExc_MemoryError, "out of memory: give a smaller size, fewer samples per pixel or fewer threads");
  } catch (const std::exception& e) {
    raise(PyExc_RuntimeError, kPython.message(e));
  }
}

void requireFile(const std::string& path, const std::string& argument) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    raise(PyExc_FileNotFoundError, argument + ": '" + path + "' not found (a scene is read from a regular file)");
}

py::array_t<float> imageArray(const Image& image) {
  py::array_t<float> out({static_cast<py::ssize_t>(image.height()), static_cast<py::ssize_t>(image.width()),
                          py::ssize_t(3)});
  const size_t row = 3 * size_t(image.width());
  for (int y = 0; y < image.height(); ++y)  // the image's row 0 is the bottom (core/image.h); the array's the top
    std::memcpy(out.mutable_data() + row * y, image.data() + row * (image.height() - 1 - y), sizeof(float) * row);
  return out;
}

}  // namespace aliaslab::python
