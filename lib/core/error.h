// Errors for bad input. Every message names where the problem is: the file
// and line, or the command-line option. Front ends catch InputError, print
// what(), write no output file and exit non-zero.
#pragma once
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

/// A bad command-line option or parameter: "<option>: <message>".
class OptionError : public InputError {
 public:
  OptionError(const std::string& option, const std::string& message)
      : InputError(option + ": " + message), option_(option) {}
  const std::string& option() const { return option_; }

 private:
  std::string option_;
};

/// Returns make(); an OptionError about option `from` (e.g. a factory's
/// "--sampler") is rethrown naming the caller's option `to` ("--samplers").
template <class Make>
auto relabelOption(const std::string& from, const std::string& to, Make&& make) -> decltype(make()) {
  try {
    return make();
  } catch (const OptionError& e) {
    if (e.option() != from) throw;
    throw OptionError(to, std::string(e.what()).substr(from.size() + 2));
  }
}

}  // namespace aliaslab
