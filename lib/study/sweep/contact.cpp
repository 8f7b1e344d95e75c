#include "study/sweep/contact.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <vector>

#include "core/error.h"
#include "core/format.h"
#include "core/picture_kit.h"

namespace aliaslab {

namespace fs = std::filesystem;

std::string configurationImageBase(const CsvRow& r) {
  return r.sampler + "-spp" + std::to_string(r.spp) + "-" + r.filter + "-r" + formatNumber(r.radius) + "-" +
         r.reconstruction + (r.prefilter == "none" ? "" : "-prefilter-" + r.prefilter);
}

void writeConfigurationImages(const std::string& dir, const std::string& base, const Image& seed0,
                              const Image& reference, const Image& noise, const Image& density) {
  const fs::path d(dir);
  writeImage((d / (base + ".png")).string(), seed0);
  Image error(seed0.width(), seed0.height()), deviation(noise.width(), noise.height());
  for (int y = 0; y < seed0.height(); ++y)
    for (int x = 0; x < seed0.width(); ++x) {
      error.set(x, y, seed0.get(x, y) - reference.get(x, y));
      deviation.set(x, y, noise.get(x, y).max(0.f).sqrt());
    }
  // each picture carries its scale: a colour bar labelled with the saturating values
  writeImage((d / (base + "-error.png")).string(),
             withColorBar(falseColor(error, kErrorScale), [](float t) { return divergingColor(2 * t - 1); },
                          "-" + formatNumber(kErrorScale), "0 (I - G)", "+" + formatNumber(kErrorScale)));
  writeImage((d / (base + "-noise.png")).string(),
             withColorBar(heatColor(deviation, kNoiseScale), heatColorOf, "0", "std dev",
                          formatNumber(kNoiseScale)));
  if (density.width() > 0) writeImage((d / (base + "-density.png")).string(), densityPanel(seed0, reference, density));
}

namespace {
using OIIO::ImageBuf;
namespace IBA = OIIO::ImageBufAlgo;

/// Draws `text` (white, 11 px) with its baseline at (x, y from the top) on an Image (y up); false without a font.
bool labelImage(Image& img, int x, int y, const std::string& text) {
  const int w = img.width(), h = img.height();
  ImageBuf buf(OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT));
  std::vector<float> rows(static_cast<size_t>(w) * h * 3);
  for (int r = 0; r < h; ++r)  // Image rows bottom-up, ImageBuf top-down
    std::copy_n(img.data() + 3 * img.index(0, h - 1 - r), 3 * w, rows.data() + 3 * static_cast<size_t>(r) * w);
  buf.set_pixels(OIIO::ROI(0, w, 0, h, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, rows.data());
  const float white[3] = {1.f, 1.f, 1.f};
  if (!IBA::render_text(buf, x, y, text, 11, "DejaVuSans", white)) return false;
  buf.get_pixels(OIIO::ROI(0, w, 0, h, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, rows.data());
  for (int r = 0; r < h; ++r)
    std::copy_n(rows.data() + 3 * static_cast<size_t>(r) * w, 3 * w, img.data() + 3 * img.index(0, h - 1 - r));
  return true;
}
}  // namespace

Image densityPanel(const Image& seed0, const Image& reference, const Image& density) {
  const int w = density.width(), h = density.height();
  float most = 1.f;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) most = std::max(most, density.get(x, y)[0]);
  Image error(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) error.set(x, y, seed0.get(x, y) - reference.get(x, y));
  const Image tiles[3] = {seed0, falseColor(error, kErrorScale), heatColor(density, most)};
  // layout: three tiles zoomed z times, then the colour bar (0 at the bottom, `most` at the top) and its labels
  const int z = std::clamp((128 + h - 1) / std::max(1, h), 1, 16), gap = 4, bar = 12, labels = 64;
  const int tw = w * z, th = h * z, margin = 14;
  Image panel(3 * (tw + gap) + bar + labels, th + 2 * margin, Color::Constant(0.12f));
  for (int t = 0; t < 3; ++t)
    for (int y = 0; y < th; ++y)
      for (int x = 0; x < tw; ++x) panel.set(t * (tw + gap) + x, margin + y, tiles[t].get(x / z, y / z));
  Image ramp(1, th);
  for (int y = 0; y < th; ++y) ramp.set(0, y, Color::Constant(most * (y + 0.5f) / th));
  const Image rampColour = heatColor(ramp, most);
  for (int y = 0; y < th; ++y)
    for (int x = 0; x < bar; ++x) panel.set(3 * (tw + gap) + x, margin + y, rampColour.get(0, y));
  // labels: samples per pixel at the top and bottom of the bar (skipped without a font)
  const int lx = 3 * (tw + gap) + bar + 3, top = panel.height() - 1;
  if (labelImage(panel, lx, top - (margin + th) + 10, formatNumber(most) + " spp"))
    labelImage(panel, lx, top - margin + 1, "0");
  return panel;
}

namespace {
using OIIO::ImageSpec;
using OIIO::ROI;

struct Tile {
  std::string method, variant, file;  ///< label lines, e.g. "jittered 16 spp" and "mitchell r=2"
  ImageBuf image;
};

/// Draws `text` with its baseline at (x, y) in the largest font size from 11
/// down to 7 that fits `width` pixels, else cut short with "..".
/// False when no font is found (the legend .txt beside the sheet remains).
bool drawLabel(ImageBuf& sheet, int x, int y, int width, const std::string& text) {
  const float white[3] = {1.f, 1.f, 1.f};
  std::string shown = text;
  int size = 11;
  for (;;) {
    const ROI box = IBA::text_size(shown, size, "DejaVuSans");
    if (!box.defined()) return false;
    if (box.width() <= width || shown.size() <= 3) break;
    if (size > 7) --size;
    else shown = text.substr(0, shown.size() - 3) + "..";  // one character shorter each time
  }
  return IBA::render_text(sheet, x, y, shown, size, "DejaVuSans", white);
}

// Pixels of a 3-channel buffer, top-down, as floats.
std::vector<float> pixels(const ImageBuf& b) {
  const ImageSpec& s = b.spec();
  std::vector<float> p(static_cast<size_t>(s.width) * s.height * 3);
  b.get_pixels(ROI(0, s.width, 0, s.height, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, p.data());
  return p;
}

// Top-left corner of the side x side window with the largest summed error.
void hardestWindow(const std::vector<double>& err, int w, int h, int side, int& bx, int& by) {
  std::vector<double> sat(static_cast<size_t>(w + 1) * (h + 1), 0.0);  // summed-area table
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      sat[(y + 1) * (w + 1) + x + 1] = err[y * w + x] + sat[y * (w + 1) + x + 1] + sat[(y + 1) * (w + 1) + x] -
                                       sat[y * (w + 1) + x];
  double best = -1;
  bx = by = 0;
  for (int y = 0; y + side <= h; ++y)
    for (int x = 0; x + side <= w; ++x) {
      const double s = sat[(y + side) * (w + 1) + x + side] - sat[y * (w + 1) + x + side] -
                       sat[(y + side) * (w + 1) + x] + sat[y * (w + 1) + x];
      if (s > best) best = s, bx = x, by = y;
    }
}

void writeSheet(const std::string& scene, const std::vector<std::vector<Tile>>& grid, const fs::path& dir) {
  const ImageSpec& s0 = grid[0][0].image.spec();
  const int w = s0.width, h = s0.height;
  // Hardest region: largest summed squared error of all tiles against the reference (tile 0).
  const std::vector<float> ref = pixels(grid[0][0].image);
  std::vector<double> err(static_cast<size_t>(w) * h, 0.0);
  for (const auto& row : grid)
    for (size_t c = 1; c < row.size(); ++c) {
      const std::vector<float> p = pixels(row[c].image);
      for (size_t i = 0; i < err.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) err[i] += (p[3 * i + ch] - ref[3 * i + ch]) * (p[3 * i + ch] - ref[3 * i + ch]);
    }
  const int side = std::max(2, std::min(w, h) / 4);
  int bx, by;
  hardestWindow(err, w, h, side, bx, by);

  // Layout: each cell is the tile, the zoomed crop below it, and a label band.
  const int tileW = 160, tileH = std::max(1, static_cast<int>(std::lround(160.0 * h / w)));
  const int label = 28, pad = 4, cellW = tileW + pad, cellH = tileH + tileW + label + pad;
  size_t cols = 0;
  for (const auto& row : grid) cols = std::max(cols, row.size());
  ImageBuf sheet(ImageSpec(static_cast<int>(cols) * cellW + pad, static_cast<int>(grid.size()) * cellH + pad, 3,
                           OIIO::TypeDesc::FLOAT));
  IBA::fill(sheet, {0.12f, 0.12f, 0.12f});
  const float outline[3] = {0.f, 1.f, 0.f};
  std::ofstream legend(dir / ("contact-" + scene + ".txt"));
  legend << "contact sheet of " << scene << ": rows top to bottom, tiles left to right; hardest window x=" << bx
         << " y=" << by << " (from the top) size " << side << "\n";
  bool fontOk = true;
  for (size_t r = 0; r < grid.size(); ++r) {
    for (size_t c = 0; c < grid[r].size(); ++c) {
      const Tile& t = grid[r][c];
      legend << "row " << r << " col " << c << ": " << t.method << ", " << t.variant << " (" << t.file << ")\n";
      ImageBuf full(ImageSpec(tileW, tileH, 3, OIIO::TypeDesc::FLOAT));
      IBA::resample(full, t.image, false);
      const float sx = static_cast<float>(tileW) / w, sy = static_cast<float>(tileH) / h;
      IBA::render_box(full, static_cast<int>(bx * sx), static_cast<int>(by * sy),
                      static_cast<int>((bx + side) * sx) - 1, static_cast<int>((by + side) * sy) - 1, outline);
      ImageBuf crop = IBA::cut(t.image, ROI(bx, bx + side, by, by + side, 0, 1, 0, 3));
      ImageBuf zoom(ImageSpec(tileW, tileW, 3, OIIO::TypeDesc::FLOAT));
      IBA::resample(zoom, crop, false);
      const int x0 = pad + static_cast<int>(c) * cellW, y0 = pad + static_cast<int>(r) * cellH;
      IBA::paste(sheet, x0, y0 + label, 0, 0, full);
      IBA::paste(sheet, x0, y0 + label + tileH, 0, 0, zoom);
      if (fontOk) fontOk = drawLabel(sheet, x0 + 2, y0 + 11, tileW - 4, t.method);
      if (fontOk) fontOk = drawLabel(sheet, x0 + 2, y0 + label - 4, tileW - 4, t.variant);
    }
  }
  const std::string path = (dir / ("contact-" + scene + ".png")).string();
  if (!sheet.write(path)) throw FileError(path, "cannot write the contact sheet: " + sheet.geterror());
}
}  // namespace

void writeContactSheets(const std::string& csvPath, const std::string& imagesDir) {
  // Per scene, keep the weighted rows at the largest spp; per (sampler, filter) the best radius.
  struct Pick { std::string base, radius; double mse; };
  std::map<std::string, std::map<std::string, std::map<std::string, Pick>>> best;  // scene -> sampler -> filter
  std::map<std::string, int> maxSpp;
  std::vector<std::vector<std::string>> rows;
  for (const std::string& line : readCsvLines(csvPath)) rows.push_back(splitCsvLine(line));
  for (const auto& f : rows)
    if (f[8] == "weighted") maxSpp[f[0]] = std::max(maxSpp[f[0]], std::stoi(f[4]));
  const size_t prefilter = csvColumn("prefilter");
  std::erase_if(rows, [&](const auto& f) { return f[prefilter] != "none"; });  // sheets compare plain sampling
  for (const auto& f : rows) {
    if (f[8] != "weighted" || std::stoi(f[4]) != maxSpp[f[0]]) continue;
    CsvRow r;
    r.sampler = f[3], r.spp = std::stoi(f[4]), r.filter = f[5], r.radius = std::stod(f[6]), r.reconstruction = f[8];
    const double mse = std::stod(f[13]);  // mse_area: accuracy against the pixel area, blur included
    auto [it, fresh] = best[f[0]][f[3]].try_emplace(f[5], Pick{configurationImageBase(r), f[6], mse});
    if (!fresh && mse < it->second.mse) it->second = Pick{configurationImageBase(r), f[6], mse};
  }
  for (const auto& [scene, samplers] : best) {
    const fs::path dir = fs::path(imagesDir) / scene;
    const fs::path refFile = dir / "reference-area.png";
    if (!fs::exists(refFile)) continue;
    std::vector<std::vector<Tile>> grid;
    for (const auto& [sampler, filters] : samplers) {
      std::vector<Tile> row;
      const std::string method = sampler + " " + std::to_string(maxSpp[scene]) + " spp";
      row.push_back({method, "reference (area)", refFile.filename().string(), ImageBuf(refFile.string())});
      for (const auto& [filter, pick] : filters) {
        const fs::path file = dir / (pick.base + ".png");
        if (fs::exists(file))
          row.push_back({method, filter + " r=" + pick.radius, file.filename().string(), ImageBuf(file.string())});
      }
      for (Tile& t : row) t.image.read(0, 0, true, OIIO::TypeDesc::FLOAT);
      if (row.size() > 1) grid.push_back(std::move(row));
    }
    if (!grid.empty()) writeSheet(scene, grid, imagesDir);
  }
}

}  // namespace aliaslab
