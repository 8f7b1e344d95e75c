// A linear RGB float image, indexed like the film: pixel (x, y) with y
// pointing up, so row 0 is the bottom of the picture. Writers flip rows so
// files read top-down as usual.
#pragma once
#include <string>
#include <vector>

#include "core/math.h"

namespace aliaslab {

class Image {
 public:
  Image() = default;
  Image(int width, int height, const Color& fill = Color::Zero());

  int width() const { return width_; }
  int height() const { return height_; }
  Color get(int x, int y) const {
    const float* p = &data_[3 * index(x, y)];
    return Color(p[0], p[1], p[2]);
  }
  void set(int x, int y, const Color& c) {
    float* p = &data_[3 * index(x, y)];
    p[0] = c[0], p[1] = c[1], p[2] = c[2];
  }
  void fill(const Color& c);
  /// Raw interleaved RGB, bottom row first.
  float* data() { return data_.data(); }
  const float* data() const { return data_.data(); }
  size_t index(int x, int y) const { return static_cast<size_t>(y) * width_ + x; }

 private:
  int width_ = 0, height_ = 0;
  std::vector<float> data_;
};

/// Writes by extension: .png and .tga as 8 bits with the classic truncation
/// int(clamp(c, 0, 1) * 255); .exr as 32-bit float, unclamped. The file is
/// written to a temporary name beside the target and renamed, so a failure
/// never leaves a half-written file. Throws FileError.
void writeImage(const std::string& path, const Image& image);

/// Reads any format OpenImageIO knows (first three channels). Throws FileError.
Image readImage(const std::string& path);

/// The size and channel count in an image file's header, read without decoding its pixels (to estimate the
/// memory a program will need before it reads them). Throws FileError.
struct ImageHeader {
  int width = 0, height = 0, channels = 0;
};
ImageHeader readImageHeader(const std::string& path);

/// Number of pixels with a NaN or infinite channel. Front ends refuse to write such an image silently
/// (raytracer, the references of sweep and reference): values beyond float range are not a picture.
size_t countNonFinitePixels(const Image& image);

/// True when the extension is one writeImage accepts (.png, .tga, .exr).
bool isSupportedImageExtension(const std::string& path);

}  // namespace aliaslab
