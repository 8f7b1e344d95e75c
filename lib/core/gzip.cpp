#include "core/gzip.h"

#include <zlib.h>

#include <algorithm>
#include <climits>
#include <fstream>
#include <iterator>

#include "core/error.h"
#include "core/files.h"

namespace aliaslab {

namespace {
constexpr int kGzipWindow = 15 + 16;  // zlib: a 32 KiB window, with the gzip header and trailer
constexpr size_t kChunk = 1 << 18;

// Gives the stream the next part of `bytes` (from `fed` on) when it has used what it had (zlib counts in 32 bits).
void feed(z_stream& s, const std::string& bytes, size_t& fed) {
  if (s.avail_in > 0 || fed >= bytes.size()) return;
  const size_t n = std::min<size_t>(bytes.size() - fed, UINT_MAX / 2);
  s.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data() + fed));
  s.avail_in = static_cast<uInt>(n);
  fed += n;
}
}  // namespace

bool isGzipPath(const std::string& path) {
  return path.size() > 3 && path.compare(path.size() - 3, 3, ".gz") == 0;
}

std::string withoutGzipSuffix(const std::string& path) {
  return isGzipPath(path) ? path.substr(0, path.size() - 3) : path;
}

bool isGzipData(const std::string& bytes) {
  return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
         static_cast<unsigned char>(bytes[1]) == 0x8b;
}

std::string gzipMember(const std::string& text) {
  z_stream s{};
  if (deflateInit2(&s, 9, Z_DEFLATED, kGzipWindow, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("zlib: cannot start a gzip member");
  std::string out;
  std::string buffer(kChunk, '\0');
  size_t fed = 0;
  int rc = Z_OK;
  do {
    feed(s, text, fed);
    s.next_out = reinterpret_cast<Bytef*>(buffer.data());
    s.avail_out = static_cast<uInt>(buffer.size());
    rc = deflate(&s, fed == text.size() ? Z_FINISH : Z_NO_FLUSH);
    out.append(buffer.data(), buffer.size() - s.avail_out);
  } while (rc == Z_OK || rc == Z_BUF_ERROR);
  deflateEnd(&s);
  if (rc != Z_STREAM_END) throw std::runtime_error("zlib: cannot compress (" + std::to_string(rc) + ")");
  return out;
}

Gunzipped gunzipMembers(const std::string& bytes) {
  Gunzipped g;
  std::string buffer(kChunk, '\0');
  while (g.completeBytes < bytes.size()) {
    z_stream s{};
    if (inflateInit2(&s, kGzipWindow) != Z_OK) throw std::runtime_error("zlib: cannot start reading gzip data");
    std::string member;
    size_t fed = g.completeBytes;
    int rc = Z_OK;
    do {
      feed(s, bytes, fed);
      s.next_out = reinterpret_cast<Bytef*>(buffer.data());
      s.avail_out = static_cast<uInt>(buffer.size());
      rc = inflate(&s, Z_NO_FLUSH);
      member.append(buffer.data(), buffer.size() - s.avail_out);
    } while (rc == Z_OK || (rc == Z_BUF_ERROR && (s.avail_in > 0 || fed < bytes.size())));
    const size_t used = fed - s.avail_in;  // where this member ends
    const std::string why = s.msg ? s.msg : "";
    inflateEnd(&s);
    if (rc != Z_STREAM_END) {
      g.cutShort = rc == Z_BUF_ERROR;
      g.damage = rc == Z_BUF_ERROR ? "a gzip member cut short (an interrupted write)"
                                   : "damaged gzip data (" + (why.empty() ? std::to_string(rc) : why) + ")";
      g.damage += " at byte " + std::to_string(g.completeBytes);
      return g;
    }
    g.text += member;
    g.completeBytes = used;
  }
  return g;
}

std::string readTextMaybeGzip(const std::string& path, bool allowTornTail) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot open for reading: " + lastSystemError());
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!isGzipData(bytes)) return bytes;
  Gunzipped g = gunzipMembers(bytes);
  if (!g.damage.empty() && !allowTornTail) throw FileError(path, g.damage);
  return std::move(g.text);
}

void writeTextMaybeGzip(const std::string& path, const std::string& text) {
  writeTextFile(path, isGzipPath(path) ? gzipMember(text) : text);
}

}  // namespace aliaslab
