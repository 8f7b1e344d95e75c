// The shared run-and-report of every experiment's main: a program states once
// how it names the library's parameters and how it exits, then runs its body.
//
//   const FrontEnd sweep{"sweep", {{"samplers", "--samplers"}, {"radius", "--radii"}, ...}};
//   return runFrontEnd(sweep, [&] { ...; return 0; });
//
// The library throws OptionError keyed by a neutral parameter name ("radius",
// "ref-spp", "grid") and writes other parameters into messages as "{key}";
// runFrontEnd turns both into this program's flags (FrontEnd::flags, the one
// place a program maps keys), prints "<program>: <message>" on stderr and
// returns the exit code: 0 done, `optionExit` for OptionError, `inputExit`
// for any other InputError (bad files), `failureExit` (after
// `failurePrefix`) for anything else. A key the map does not hold is printed
// as it is (errors the front end throws itself already name its flag).
#pragma once
#include <exception>
#include <functional>
#include <map>
#include <string>

namespace aliaslab {

struct FrontEnd {
  std::string program;                       ///< the name printed before every message
  std::map<std::string, std::string> flags;  ///< library key -> this program's flag
  int optionExit = 2;                        ///< OptionError
  int inputExit = 2;                         ///< any other InputError
  int failureExit = 1;                       ///< any other exception
  std::string failurePrefix = "failed: ";    ///< before the message of any other exception

  /// The flag of `key` (leading dashes ignored); the key itself when the map does not hold it.
  std::string flag(const std::string& key) const;
  /// The message of `e` in this program's terms: an OptionError as "<flag>: <message>", every "{key}" of the
  /// map replaced by its flag.
  std::string message(const std::exception& e) const;
};

/// Runs `body` and returns its exit code; an exception is printed as "<program>: <message>" (see the top of
/// this file) and returns the program's exit code for it.
int runFrontEnd(const FrontEnd& program, const std::function<int()>& body);

}  // namespace aliaslab
