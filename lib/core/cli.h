// Command-line parsing shared by the experiment front ends (CLI11).
#pragma once
#include <CLI/CLI.hpp>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace aliaslab {

/// A seed: a whole number >= 0 (CLI11's NonNegativeNumber would print its range up to DBL_MAX).
inline const CLI::Validator kSeed(
    [](std::string& text) -> std::string {
      const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
      return digits && text.size() <= 19 ? std::string() : "a seed is a whole number >= 0, found '" + text + "'";
    },
    "");

/// Every numeric option must be finite: CLI11 reads "nan", "inf" or "1e999" into a double without complaint.
/// Throws CLI::ValidationError naming the option when a value of an option with a numeric type (FLOAT, INT,
/// NUMBER, also inside comma lists and from --config files) is not a finite number.
inline void refuseNonFiniteNumbers(const CLI::App& app) {
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->count() == 0) continue;
    const std::string type = opt->get_type_name();
    if (type.find("FLOAT") == std::string::npos && type.find("INT") == std::string::npos &&
        type.find("NUMBER") == std::string::npos)
      continue;
    for (const std::string& given : opt->results()) {
      size_t start = 0;
      for (;;) {
        const size_t comma = given.find(',', start);
        std::string v = given.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        while (!v.empty() && std::isspace(static_cast<unsigned char>(v.back()))) v.pop_back();
        char* end = nullptr;
        const char* text = v.c_str();
        while (std::isspace(static_cast<unsigned char>(*text))) ++text;
        const double d = std::strtod(text, &end);
        if (end != text && *end == '\0' && !std::isfinite(d))
          throw CLI::ValidationError(opt->get_name(), "must be a finite number, found '" + v + "'");
        if (comma == std::string::npos) break;
        start = comma + 1;
      }
    }
  }
}

/// Parses argv into `app`. Returns -1 when the program should go on;
/// otherwise the exit code: 0 after printing --help, 2 after printing a
/// usage error as "<program>: <message>" (CLI11's own codes are not used,
/// so every front end exits 2 for bad options).
inline int parseCommandLine(CLI::App& app, int argc, char** argv, const char* program) {
  try {
    app.parse(argc, argv);
    refuseNonFiniteNumbers(app);
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
