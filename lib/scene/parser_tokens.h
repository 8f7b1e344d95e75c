// Private to the scene parser: the token stream and typed readers.
//
// A scene file is split once into whitespace-separated tokens, each with its
// line number; `{` and `}` are always tokens of their own and `#` starts a
// comment that runs to the end of the line. Readers consume tokens and throw
// ParseError "<file>:<line>: expected <what>, found '<token>'" on mismatch,
// reporting the end of the file as "found end of file".
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "core/math.h"

namespace aliaslab::detail {

struct Token {
  std::string text;
  int line = 0;
};

class TokenStream {
 public:
  /// Splits `text`; `file` names the source in messages.
  TokenStream(const std::string& text, std::string file);

  bool atEnd() const { return pos_ >= tokens_.size(); }
  /// The next token without consuming it; at the end, an empty token on the last line.
  const Token& peek() const { return atEnd() ? end_ : tokens_[pos_]; }
  /// Consumes the next token; throws "expected <what>" at the end of the file.
  const Token& next(const std::string& what);
  size_t position() const { return pos_; }
  void seek(size_t pos) { pos_ = pos; }
  /// Index of the token after the `}` matching the `{` at `open` (nested braces skipped).
  size_t skipBlock(size_t open, const std::string& block) const;

  /// Consumes `word` or throws "expected '<word>' <context>, found ...".
  void expect(const std::string& word, const std::string& context = {});
  /// A finite float for field `field`.
  float number(const std::string& field);
  /// A whole number for field `field`, in [minimum, maximum].
  int integer(const std::string& field, int minimum, int maximum);
  /// Three finite floats for field `field`.
  Vec3 vec3(const std::string& field);

  /// Throws ParseError(file, line, message).
  [[noreturn]] void fail(int line, const std::string& message) const;
  /// "'<text>'" or "end of file", for "found ..." in messages.
  static std::string describe(const Token& token);
  const std::string& file() const { return file_; }
  int lastLine() const { return end_.line; }

 private:
  std::string file_;
  std::vector<Token> tokens_;
  Token end_;
  size_t pos_ = 0;
};

}  // namespace aliaslab::detail
