#include "study/reference/manifest.h"

#include <cctype>
#include <string>

#include "core/error.h"
#include "core/format.h"

namespace aliaslab {

namespace {
std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (static_cast<unsigned char>(c) < 0x20) out += ' ';
    else out += c;
  }
  return out + "\"";
}

std::string fieldText(const ManifestField& f) {
  return jsonString(f.key) + ": " + (f.quoted ? jsonString(f.value) : f.value);
}

// A reader of the JSON subset the writer writes: one object of strings, numbers, lists of numbers and one list of
// objects of strings and numbers.
class Reader {
 public:
  Reader(const std::string& text, const std::string& path) : s_(text), path_(path) {}

  Manifest manifest() {
    Manifest m;
    object([&](const std::string& key) {
      if (key == "filters" && take('[')) {
        if (take(']')) return;
        do {
          m.filters.emplace_back();
          object([&](const std::string& k) { m.filters.back().push_back(value(k)); });
        } while (take(','));
        expect(']');
      } else {
        m.head.push_back(value(key));
      }
    });
    if (peek() != '\0') fail("text after the manifest");
    return m;
  }

 private:
  // `{"key": <member(key)>, ...}`
  template <class Member>
  void object(Member member) {
    expect('{');
    if (take('}')) return;
    do {
      const std::string key = string();
      expect(':');
      member(key);
    } while (take(','));
    expect('}');
  }
  ManifestField value(const std::string& key) {
    if (peek() == '"') return {key, string(), true};
    const size_t start = at_;
    if (peek() == '[') {  // a list of numbers, kept as its text
      const size_t end = s_.find(']', at_);
      if (end == std::string::npos) fail("an unclosed list");
      at_ = end + 1;
    } else {
      auto inNumber = [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
      };
      while (at_ < s_.size() && inNumber(s_[at_])) ++at_;
    }
    if (at_ == start) fail("a value");
    return {key, s_.substr(start, at_ - start), false};
  }
  std::string string() {
    expect('"');
    std::string out;
    while (at_ < s_.size() && s_[at_] != '"') {
      if (s_[at_] == '\\' && at_ + 1 < s_.size()) ++at_;
      out += s_[at_++];
    }
    expect('"');
    return out;
  }
  char peek() {
    while (at_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[at_]))) ++at_;
    return at_ < s_.size() ? s_[at_] : '\0';
  }
  bool take(char c) {
    if (peek() != c) return false;
    ++at_;
    return true;
  }
  void expect(char c) {
    if (!take(c)) fail(std::string("'") + c + "'");
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw FileError(path_, "not a reference manifest: expected " + what + " at character " + std::to_string(at_));
  }

  const std::string& s_;
  const std::string& path_;
  size_t at_ = 0;
};
}  // namespace

std::string manifestValue(const ManifestFields& fields, const std::string& key) {
  for (const ManifestField& f : fields)
    if (f.key == key) return f.value;
  return {};
}

std::string writeManifest(const Manifest& m) {
  std::string j = "{";
  for (const ManifestField& f : m.head) j += "\n  " + fieldText(f) + ",";
  j += "\n  \"filters\": [";
  for (size_t i = 0; i < m.filters.size(); ++i) {
    j += std::string(i ? "," : "") + "\n    {";
    for (size_t k = 0; k < m.filters[i].size(); ++k) j += (k ? ", " : "") + fieldText(m.filters[i][k]);
    j += "}";
  }
  return j + "\n  ]\n}\n";
}

Manifest readManifest(const std::string& json, const std::string& path) { return Reader(json, path).manifest(); }

std::string referenceManifest(const StudyScene& scene, const ReferenceSet& set,
                              const std::vector<std::string>& imageNames,
                              const std::vector<std::string>& imageHashes,
                              const std::vector<std::string>& diffHashes) {
  auto number = [](const std::string& key, const std::string& text) { return ManifestField{key, text, false}; };
  Manifest m;
  m.head = {{"scene", scene.stem}, {"scene_path", manifestScenePath(scene.path)},
            number("width", std::to_string(scene.width)), number("height", std::to_string(scene.height)),
            {"tracing", describeTraceOptions(scene.options)}};
  if (scene.filmOffset[0] != 0 || scene.filmOffset[1] != 0)  // a shifted camera (study/sweep/alignment.h)
    m.head.push_back(number("film_offset", "[" + formatReal(scene.filmOffset[0]) + ", " +
                                               formatReal(scene.filmOffset[1]) + "]"));
  m.head.insert(m.head.end(), {number("spp", std::to_string(set.spp)), {"sampler", set.sampler},
                               number("seed", std::to_string(set.seed)), {"git_revision", gitRevision()},
                               number("seconds", formatReal(set.seconds))});
  for (size_t i = 0; i < set.images.size(); ++i) {
    const ReferenceImage& r = set.images[i];
    ManifestFields e = {{"filter", r.filter.first}, number("radius", formatReal(r.filter.second)),
                        {"describe", r.describe}, number("ref_error", formatReal(r.error)),
                        number("undefined_pixels", std::to_string(r.stats.undefinedPixels)), {"key", r.key},
                        {"image", i < imageNames.size() ? imageNames[i] : ""}};
    if (i < imageHashes.size()) e.push_back({"image_hash", imageHashes[i]});
    if (i < diffHashes.size()) e.push_back({"diff_hash", diffHashes[i]});
    m.filters.push_back(std::move(e));
  }
  return writeManifest(m);
}

}  // namespace aliaslab
