#include "scene/render_settings.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/error.h"

namespace aliaslab {
namespace {

/// The keywords of one render line (the text after "# render:") into `r`; `lineNo` for messages.
void readKeywords(const std::string& after, const std::string& file, int lineNo, RenderSettings& r) {
  std::istringstream ss(after);
  std::vector<std::string> tok;
  for (std::string t; ss >> t;) tok.push_back(t);
  auto fail = [&](const std::string& what) { throw ParseError(file, lineNo, "render line: " + what); };
  auto number = [&](size_t& k, const std::string& flag) {
    if (k + 1 >= tok.size()) fail(flag + " needs a value");
    try {
      size_t used = 0;
      const double v = std::stod(tok[++k], &used);
      if (used != tok[k].size() || !std::isfinite(v)) throw std::invalid_argument("x");
      return v;
    } catch (const std::exception&) {
      fail("expected a number after " + flag + ", found '" + tok[k] + "'");
    }
    return 0.0;
  };
  for (size_t k = 0; k < tok.size(); ++k) {
    const std::string& f = tok[k];
    if (f == "-size") {
      r.width = static_cast<int>(number(k, f));
      r.height = static_cast<int>(number(k, f));
      if (r.width < 1 || r.height < 1) fail("-size must be positive");
    } else if (f == "-shadows") {
      r.shadows = true;
    } else if (f == "-shade_back") {
      r.shadeBack = true;
    } else if (f == "-bounces") {
      r.bounces = static_cast<int>(number(k, f));
      if (r.bounces < 0 || r.bounces > kMaxBounces) fail("-bounces must be in 0.." + std::to_string(kMaxBounces));
    } else if (f == "-weight") {
      r.weight = static_cast<float>(number(k, f));
    } else if (f == "-grid") {
      for (int& g : r.grid) g = static_cast<int>(number(k, f));
      if (r.grid[0] < 0 || r.grid[1] < 0 || r.grid[2] < 0) fail("-grid resolutions must be >= 0 (0 = automatic)");
    } else {
      fail("unknown flag '" + f + "' (expected -size, -shadows, -bounces, -weight, -shade_back, -grid)");
    }
  }
  if (r.width == 0) fail("missing -size W H");
}

}  // namespace

RenderSettings parseRenderLine(const std::string& text, const std::string& file) {
  RenderSettings r;
  int lineNo = 1;
  for (size_t begin = 0; begin < text.size(); ++lineNo) {
    // Line breaks as the scene parser reads them: "\n", "\r\n" or a lone "\r".
    size_t end = text.find_first_of("\r\n", begin);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(begin, end - begin);
    begin = end + (end < text.size() && text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? 2 : 1);
    const size_t at = line.find("# render:");
    if (at == std::string::npos) continue;
    readKeywords(line.substr(at + 9), file, lineNo, r);
    r.found = true;
    r.line = lineNo;
    return r;
  }
  return r;
}

}  // namespace aliaslab
