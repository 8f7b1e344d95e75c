// Command-line parsing shared by the experiment front ends (CLI11).
#pragma once
#include <CLI/CLI.hpp>
#include <cstdio>

namespace aliaslab {

/// A seed: a whole number >= 0 (CLI11's NonNegativeNumber would print its range up to DBL_MAX).
inline const CLI::Validator kSeed(
    [](std::string& text) -> std::string {
      const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
      return digits && text.size() <= 19 ? std::string() : "a seed is a whole number >= 0, found '" + text + "'";
    },
    "");

/// Parses argv into `app`. Returns -1 when the program should go on;
/// otherwise the exit code: 0 after printing --help, 2 after printing a
/// usage error as "<program>: <message>" (CLI11's own codes are not used,
/// so every front end exits 2 for bad options).
inline int parseCommandLine(CLI::App& app, int argc, char** argv, const char* program) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "%s: %s\nRun with --help for the options.\n", program, e.what());
    return 2;
  }
  return -1;
}

}  // namespace aliaslab
