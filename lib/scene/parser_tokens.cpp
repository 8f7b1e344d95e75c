#include "scene/parser_tokens.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/error.h"

namespace aliaslab::detail {

TokenStream::TokenStream(const std::string& text, std::string file) : file_(std::move(file)) {
  // Split on whitespace, braces as tokens, '#' comments to end of line.
  int line = 1;  // current line while splitting
  std::string word;
  int wordLine = 1;
  auto flush = [&] {
    if (!word.empty()) tokens_.push_back({word, wordLine});
    word.clear();
  };
  bool comment = false;
  for (size_t i = 0; i < text.size(); ++i) {
    // Line breaks: "\n", "\r\n" and a lone "\r" (old Mac files), so a CR-only file is not one long comment.
    const char ch = text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n') ? '\n' : text[i];
    if (ch == '\n') {
      flush();
      comment = false;
      ++line;
      continue;
    }
    if (comment) continue;
    if (ch == '#') {
      flush();
      comment = true;
    } else if (ch == '{' || ch == '}') {
      flush();
      tokens_.push_back({std::string(1, ch), line});
    } else if (ch == ' ' || ch == '\t' || ch == '\r' || ch == '\f' || ch == '\v') {
      flush();
    } else {
      if (word.empty()) wordLine = line;
      word += ch;
    }
  }
  flush();
  end_.line = tokens_.empty() ? 1 : tokens_.back().line;  // end-of-file errors point at the last token
}

const Token& TokenStream::next(const std::string& what) {
  if (atEnd()) fail(end_.line, "unexpected end of file: expected " + what);
  return tokens_[pos_++];
}

size_t TokenStream::skipBlock(size_t open, const std::string& block) const {
  int depth = 0;
  for (size_t i = open; i < tokens_.size(); ++i) {
    if (tokens_[i].text == "{") ++depth;
    else if (tokens_[i].text == "}" && --depth == 0) return i + 1;
  }
  const int line = open < tokens_.size() ? tokens_[open].line : end_.line;
  fail(end_.line, "unexpected end of file: expected '}' closing the " + block + " block opened at line " +
                      std::to_string(line));
}

void TokenStream::expect(const std::string& word, const std::string& context) {
  const std::string what = "'" + word + "'" + (context.empty() ? "" : " " + context);
  const Token& t = next(what);
  if (t.text != word) fail(t.line, "expected " + what + ", found " + describe(t));
}

float TokenStream::number(const std::string& field) {
  const Token& t = next("a number for '" + field + "'");
  const char* first = t.text.data();
  const char* last = first + t.text.size();
  if (first != last && *first == '+') ++first;
  float value = 0.f;
  auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec == std::errc::result_out_of_range)
    fail(t.line, "number out of range for '" + field + "': " + describe(t));
  if (ec != std::errc() || ptr != last || first == last)
    fail(t.line, "expected a number for '" + field + "', found " + describe(t));
  if (!std::isfinite(value))
    fail(t.line, "expected a finite number for '" + field + "', found " + describe(t));
  return value;
}

int TokenStream::integer(const std::string& field, int minimum, int maximum) {
  const Token& t = next("a whole number for '" + field + "'");
  const char* first = t.text.data();
  const char* last = first + t.text.size();
  if (first != last && *first == '+') ++first;
  long long value = 0;
  auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || ptr != last || first == last)
    fail(t.line, "expected a whole number for '" + field + "', found " + describe(t));
  if (value < minimum || value > maximum)
    fail(t.line, "'" + field + "' must be in [" + std::to_string(minimum) + ", " + std::to_string(maximum) +
                     "], found " + describe(t));
  return static_cast<int>(value);
}

Vec3 TokenStream::vec3(const std::string& field) {
  Vec3 v;
  for (int i = 0; i < 3; ++i) v[i] = number(field);
  return v;
}

void TokenStream::fail(int line, const std::string& message) const { throw ParseError(file_, line, message); }

std::string TokenStream::describe(const Token& token) {
  if (token.text.empty()) return "end of file";
  // printable as it is; other bytes (a NUL would cut the message short) as \xNN; long tokens cut at 60 bytes
  std::string out = "'";
  for (size_t i = 0; i < token.text.size() && i < 60; ++i) {
    const unsigned char c = static_cast<unsigned char>(token.text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    }
  }
  return out + (token.text.size() > 60 ? "...'" : "'");
}

}  // namespace aliaslab::detail
