// Command-line parsing shared by the experiment front ends (CLI11).
#pragma once
#include <CLI/CLI.hpp>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

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

/// Checks a --config file strictly before CLI11 reads it (CLI11 silently drops unknown keys and every key under
/// a [section]): every line must be blank, a comment (# or ;) or `key = value` with `key` a long option of
/// `app` (without the dashes; '_' may stand for '-'). Returns "" or "<file>:<line>: <problem>".
inline std::string checkConfigFile(const CLI::App& app, const std::string& path) {
  std::ifstream in(path);
  if (!in) return path + ": cannot open the --config file";
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    auto trim = [](std::string t) {
      const size_t a = t.find_first_not_of(" \t\r"), b = t.find_last_not_of(" \t\r");
      return a == std::string::npos ? std::string() : t.substr(a, b - a + 1);
    };
    const std::string t = trim(line);
    const std::string where = path + ":" + std::to_string(n) + ": ";
    if (t.empty() || t[0] == '#' || t[0] == ';') continue;
    if (t[0] == '[')
      return where + "section " + t + " is not supported: write the options as top-level keys (e.g. seeds = 8)";
    const size_t eq = t.find('=');
    if (eq == std::string::npos) return where + "expected 'key = value', found '" + t + "'";
    std::string key = trim(t.substr(0, eq));
    if (key.size() >= 2 && (key.front() == '"' || key.front() == '\'') && key.back() == key.front())
      key = key.substr(1, key.size() - 2);
    std::string dashed = key;
    for (char& c : dashed) c = c == '_' ? '-' : c;
    const CLI::Option* opt = app.get_option_no_throw("--" + key);
    if (!opt) opt = app.get_option_no_throw("--" + dashed);
    if (!opt || key.empty() || key.rfind("-", 0) == 0 || opt == app.get_config_ptr() || opt == app.get_help_ptr())
      return where + "unknown key '" + key + "' (keys are the long option names of --help, without the dashes)";
  }
  return {};
}

/// Parses argv into `app`. Returns -1 when the program should go on;
/// otherwise the exit code: 0 after printing --help, 2 after printing a
/// usage error as "<program>: <message>" (CLI11's own codes are not used,
/// so every front end exits 2 for bad options).
inline int parseCommandLine(CLI::App& app, int argc, char** argv, const char* program) {
  if (const CLI::Option* config = app.get_config_ptr())
    for (int i = 1; i + 1 < argc; ++i) {
      const std::string a = argv[i];
      std::string file;
      for (const std::string& name : config->get_lnames())
        if (a == "--" + name) file = argv[i + 1];
        else if (a.rfind("--" + name + "=", 0) == 0) file = a.substr(name.size() + 3);
      if (file.empty()) continue;
      if (const std::string problem = checkConfigFile(app, file); !problem.empty()) {
        std::fprintf(stderr, "%s: --config: %s\n", program, problem.c_str());
        return 2;
      }
    }
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
