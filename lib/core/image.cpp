#include "core/image.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <system_error>

#include "core/error.h"
#include "core/files.h"

namespace aliaslab {

Image::Image(int width, int height, const Color& fill) : width_(width), height_(height) {
  data_.resize(static_cast<size_t>(width) * height * 3);
  this->fill(fill);
}

void Image::fill(const Color& c) {
  for (size_t i = 0; i < data_.size(); i += 3) data_[i] = c[0], data_[i + 1] = c[1], data_[i + 2] = c[2];
}

namespace {
std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return std::tolower(ch); });
  return ext;
}
}  // namespace

size_t countNonFinitePixels(const Image& image) {
  size_t n = 0;
  const size_t pixels = static_cast<size_t>(image.width()) * image.height();
  for (size_t i = 0; i < pixels; ++i) {
    const float* p = image.data() + 3 * i;
    n += !(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
  }
  return n;
}

bool isSupportedImageExtension(const std::string& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".png" || ext == ".tga" || ext == ".exr";
}

void writeImage(const std::string& path, const Image& image) {
  if (!isSupportedImageExtension(path))
    throw FileError(path, "unsupported image extension (use .png, .tga or .exr)");
  const bool eightBit = lowerExtension(path) != ".exr";
  const int w = image.width(), h = image.height();

  // Flip to top-down rows; quantise with the classic truncation for 8-bit files.
  std::vector<float> flt;
  std::vector<uint8_t> bytes;
  if (eightBit) bytes.resize(static_cast<size_t>(w) * h * 3);
  else flt.resize(static_cast<size_t>(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const float v = image.data()[3 * image.index(x, h - 1 - y) + c];
        const size_t o = 3 * (static_cast<size_t>(y) * w + x) + c;
        if (eightBit) bytes[o] = static_cast<uint8_t>(std::clamp(v, 0.f, 1.f) * 255.f);
        else flt[o] = v;
      }

  // Write beside the target, then rename: no half-written output.
  // Links are followed; a device or FIFO is refused (an image is written whole, then renamed into place).
  const OutputTarget where = outputTarget(path);
  if (where.special)
    throw FileError(path, "not a regular file (a device, FIFO or socket): images are written to regular files only");
  if (const std::string kind = specialFileKind(where.path); kind == "a folder")
    throw FileError(path, "is a folder: an image cannot replace it");
  const std::filesystem::path target(where.path);
  const std::filesystem::path tmp = temporaryPathFor(where.path);
  auto out = OIIO::ImageOutput::create(path);
  if (!out) throw FileError(path, "cannot create an image writer: " + OIIO::geterror());
  OIIO::ImageSpec spec(w, h, 3, eightBit ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
  if (!out->open(tmp.string(), spec)) throw FileError(path, "cannot open for writing: " + out->geterror());
  errno = 0;
  const bool ok = eightBit ? out->write_image(OIIO::TypeDesc::UINT8, bytes.data())
                           : out->write_image(OIIO::TypeDesc::FLOAT, flt.data());
  const bool closed = out->close();
  std::error_code ec;
  if (!ok || !closed) {
    const std::string why = out->geterror() + (errno ? " (" + lastSystemError() + ")" : std::string());
    std::filesystem::remove(tmp, ec);
    throw FileError(path, "write failed: " + why);
  }
  std::filesystem::rename(tmp, target, ec);
  if (ec) {
    const std::string why = ec.message();  // (before remove() reuses ec)
    std::filesystem::remove(tmp, ec);
    throw FileError(path, "cannot move the finished image into place: " + why);
  }
}

ImageHeader readImageHeader(const std::string& path) {
  requireRegularFile(path, "an image is read from a regular file");
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw FileError(path, "cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  return {spec.width, spec.height, spec.nchannels};
}

Image readImage(const std::string& path) {
  requireRegularFile(path, "an image is read from a regular file");  // a FIFO would block the reader
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw FileError(path, "cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  const int w = spec.width, h = spec.height, nc = spec.nchannels;
  std::vector<float> pixels(static_cast<size_t>(w) * h * nc);
  if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, pixels.data()))
    throw FileError(path, "cannot read image: " + in->geterror());
  Image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float* p = &pixels[(static_cast<size_t>(h - 1 - y) * w + x) * nc];
      image.set(x, y, Color(p[0], nc > 1 ? p[1] : p[0], nc > 2 ? p[2] : p[0]));
    }
  return image;
}

}  // namespace aliaslab
