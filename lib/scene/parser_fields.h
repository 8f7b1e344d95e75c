// Private to the scene parser: a block of named fields in any order.
//
// Reads `name value ...` pairs up to and including the closing `}` of a
// block such as `Sphere { center 0 0 0 radius 1 }`. Each name may appear at
// most once; an unknown name, a repeated name or a bad value throws
// ParseError naming the block, the field and the line. Callers then read
// values with defaults and check required fields with require().
#pragma once
#include <climits>
#include <map>
#include <string>
#include <vector>

#include "scene/parser_tokens.h"

namespace aliaslab::detail {

enum class FieldKind { Number, Integer, Vec3, Word };

struct FieldSpec {
  std::string name;
  FieldKind kind = FieldKind::Number;
  int minimum = INT_MIN;  ///< bounds of an Integer field
  int maximum = INT_MAX;
};

class FieldBlock {
 public:
  FieldBlock(TokenStream& tokens, std::string block, std::vector<FieldSpec> spec);

  bool has(const std::string& name) const { return values_.count(name) != 0; }
  float number(const std::string& name, float fallback = 0.f) const;
  int integer(const std::string& name, int fallback = 0) const;
  Vec3 vec3(const std::string& name, const Vec3& fallback = Vec3::Zero()) const;
  std::string word(const std::string& name) const;
  /// Line of the field's name, or of the closing brace when absent.
  int line(const std::string& name) const;
  /// Throws "<block>: missing field '<name>'" at the closing brace for the first absent name.
  void require(const std::vector<std::string>& names) const;
  /// Throws "<block>: '<name>' <message>" at the field's line.
  [[noreturn]] void fail(const std::string& name, const std::string& message) const;

 private:
  struct Entry {
    Vec3 v = Vec3::Zero();
    int i = 0;
    std::string w;
    int line = 0;
  };
  TokenStream& tokens_;
  std::string block_;
  std::vector<FieldSpec> spec_;
  std::map<std::string, Entry> values_;
  int closeLine_ = 0;
};

}  // namespace aliaslab::detail
