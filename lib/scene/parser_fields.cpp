#include "scene/parser_fields.h"

namespace aliaslab::detail {

FieldBlock::FieldBlock(TokenStream& tokens, std::string block, std::vector<FieldSpec> spec)
    : tokens_(tokens), block_(std::move(block)), spec_(std::move(spec)) {
  for (;;) {
    const Token& t = tokens_.next("a field of " + block_ + " or '}'");
    if (t.text == "}") {
      closeLine_ = t.line;
      return;
    }
    const FieldSpec* field = nullptr;
    for (const FieldSpec& s : spec_)
      if (s.name == t.text) field = &s;
    if (!field) {
      std::string names;
      for (const FieldSpec& s : spec_) names += "'" + s.name + "', ";
      tokens_.fail(t.line, "unknown field " + TokenStream::describe(t) + " in " + block_ + ": expected " +
                               (names.empty() ? "'}'" : "one of " + names + "or '}'"));
    }
    if (auto it = values_.find(field->name); it != values_.end())
      tokens_.fail(t.line, block_ + ": field '" + field->name + "' given twice (first at line " +
                               std::to_string(it->second.line) + ")");
    Entry e;
    e.line = t.line;
    switch (field->kind) {
      case FieldKind::Number: e.v[0] = tokens_.number(field->name); break;
      case FieldKind::Integer: e.i = tokens_.integer(field->name, field->minimum, field->maximum); break;
      case FieldKind::Vec3: e.v = tokens_.vec3(field->name); break;
      case FieldKind::Word: {
        const Token& w = tokens_.next("a value for '" + field->name + "'");
        if (w.text == "{" || w.text == "}")
          tokens_.fail(w.line, "expected a value for '" + field->name + "', found " + TokenStream::describe(w));
        e.w = w.text;
        break;
      }
    }
    values_.emplace(field->name, std::move(e));
  }
}

float FieldBlock::number(const std::string& name, float fallback) const {
  auto it = values_.find(name);
  return it == values_.end() ? fallback : it->second.v[0];
}

int FieldBlock::integer(const std::string& name, int fallback) const {
  auto it = values_.find(name);
  return it == values_.end() ? fallback : it->second.i;
}

Vec3 FieldBlock::vec3(const std::string& name, const Vec3& fallback) const {
  auto it = values_.find(name);
  return it == values_.end() ? fallback : it->second.v;
}

std::string FieldBlock::word(const std::string& name) const {
  auto it = values_.find(name);
  return it == values_.end() ? std::string() : it->second.w;
}

int FieldBlock::line(const std::string& name) const {
  auto it = values_.find(name);
  return it == values_.end() ? closeLine_ : it->second.line;
}

void FieldBlock::require(const std::vector<std::string>& names) const {
  for (const std::string& n : names)
    if (!has(n)) tokens_.fail(closeLine_, block_ + ": missing field '" + n + "' before '}'");
}

void FieldBlock::fail(const std::string& name, const std::string& message) const {
  tokens_.fail(line(name), block_ + ": '" + name + "' " + message);
}

}  // namespace aliaslab::detail
