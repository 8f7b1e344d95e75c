// Text files kept gzipped: a path ending in ".gz" is written compressed, and any file is read back as text
// whether or not it is compressed (told by the gzip magic bytes, not by the name).
//
// A gzip file may hold several members one after the other; its text is their texts joined (RFC 1952; zlib
// and Python's gzip read it so). That is how a gzipped CSV grows: each append writes one whole member in one
// write(), so a killed run leaves at most one torn member at the end, which readers that allow it drop (the
// text of the complete members is kept) as a plain CSV's reader drops a torn last line.
// Members are written deterministically (zlib's level 9, no name, modification time 0): the same text gives
// the same bytes, as `gzip -9 -n` would.
#pragma once
#include <cstddef>
#include <string>

namespace aliaslab {

/// Whether `path` names a file the writers compress (its name ends in ".gz").
bool isGzipPath(const std::string& path);

/// `path` without a trailing ".gz" ("out/study.csv.gz" -> "out/study.csv").
std::string withoutGzipSuffix(const std::string& path);

/// Whether `bytes` begin with the gzip magic (0x1f 0x8b).
bool isGzipData(const std::string& bytes);

/// One gzip member holding `text`.
std::string gzipMember(const std::string& text);

/// The text of gzip data read member by member.
struct Gunzipped {
  std::string text;         ///< the texts of the complete members, joined
  size_t completeBytes = 0; ///< the bytes of `bytes` those members occupy (where a torn tail starts)
  std::string damage;       ///< "" when every byte belongs to a complete member; else what is wrong after them
  bool cutShort = false;    ///< the damage is only a last member cut short (a killed write), not bad data
};
/// Decompresses the members of `bytes` one after the other, stopping at the first that is cut short or damaged.
Gunzipped gunzipMembers(const std::string& bytes);

/// The text of a file, decompressed when it is gzip data. A torn or damaged tail after the complete members
/// is dropped when `allowTornTail`, else it throws FileError naming the file and what is wrong.
std::string readTextMaybeGzip(const std::string& path, bool allowTornTail);

/// Writes `text` to `path` atomically (core/files.h writeTextFile), as one gzip member when isGzipPath(path).
void writeTextMaybeGzip(const std::string& path, const std::string& text);

}  // namespace aliaslab
