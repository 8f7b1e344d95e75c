// Errors for bad input. Every message names where the problem is: the file
// and line, or the parameter (OptionError's key). Front ends catch InputError, print
// what(), write no output file and exit non-zero.
#pragma once
#include <algorithm>
#include <stdexcept>
#include <string>

namespace aliaslab {

/// Base of all user-input errors; what() is the complete message.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A malformed scene or OBJ file: "<file>:<line>: <message>".
class ParseError : public InputError {
 public:
  ParseError(const std::string& file, int line, const std::string& message)
      : InputError(file + ":" + std::to_string(line) + ": " + message), file_(file), line_(line) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }

 private:
  std::string file_;
  int line_;
};

/// A file that cannot be opened, read or written: "<file>: <message>".
class FileError : public InputError {
 public:
  FileError(const std::string& file, const std::string& message) : InputError(file + ": " + message) {}
};

/// A bad parameter: "<key>: <message>". The key is the library's neutral
/// name of the parameter ("radius", "samplers", "ref-spp", "grid"), never a
/// command-line flag: each front end maps keys to its own flags in one place
/// (experiments/common/front_end.h). A message that must name another
/// parameter writes its key in braces ("give another {out}"), which the front
/// end replaces by its flag too.
class OptionError : public InputError {
 public:
  OptionError(const std::string& key, const std::string& message)
      : InputError(key + ": " + message), key_(key), message_(message) {}
  const std::string& key() const { return key_; }
  const std::string& message() const { return message_; }

 private:
  std::string key_;
  std::string message_;
};

/// Returns make(); an OptionError about key `from` (e.g. a factory's
/// "sampler") is rethrown under the caller's key `to` (its list "samplers"),
/// so the error names the parameter the caller was given.
template <class Make>
auto rekeyOption(const std::string& from, const std::string& to, Make&& make) -> decltype(make()) {
  try {
    return make();
  } catch (const OptionError& e) {
    if (e.key() != from) throw;
    throw OptionError(to, e.message());
  }
}

}  // namespace aliaslab
