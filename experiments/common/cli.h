// Command-line parsing shared by the experiment front ends (CLI11), and the
// one grammar they all follow:
//   - options are long, double-dash, lower case with dashes (--max-n); the
//     raytracer's classic course flags (-input, -size, ...) are the only
//     single-dash ones;
//   - a list is one comma-separated value (--samplers random,sobol); plural
//     names take lists, singular names one value (--sampler in the
//     raytracer, --samplers in the studies);
//   - --out names a folder, --output a file;
//   - every program has --help (defaults and ranges shown, as
//     "(default: ...)" and "[lo..hi]") and --version (git revision and build
//     type);
//   - bad options exit 2 with "<program>: <message>".
// setupCommandLine installs the help layout (HelpFormatter) and --version;
// tests/programs/cli_grammar_test.cpp checks every executable of experiments/. Errors
// after parsing go through front_end.h (runFrontEnd: keys -> flags, exit codes).
#pragma once
#include <CLI/CLI.hpp>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "core/files.h"
#include "core/version.h"

namespace aliaslab {

/// A seed: a whole number >= 0 (CLI11's NonNegativeNumber would print its range up to DBL_MAX).
inline const CLI::Validator kSeed(
    [](std::string& text) -> std::string {
      const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
      return digits && text.size() <= 19 ? std::string() : "a seed is a whole number >= 0, found '" + text + "'";
    },
    "");

/// The help layout of every front end: option names without CLI11's flag
/// defaults ("--no-chart", not "--no-chart{false}"), a value placeholder
/// without validator text ("N", not "INT:INT in [2 - 1048576]"), lists as
/// "TEXT,..." and the default, range and choices in the description.
class HelpFormatter : public CLI::Formatter {
 public:
  std::string make_option_name(const CLI::Option* opt, bool positional) const override {
    if (positional) return opt->get_name(true, false);
    std::string names;
    for (const std::string& s : opt->get_snames()) names += (names.empty() ? "-" : ", -") + s;
    for (const std::string& l : opt->get_lnames()) names += (names.empty() ? "--" : ", --") + l;
    return names;
  }
  std::string make_option_opts(const CLI::Option* opt) const override {
    if (!opt->get_option_text().empty()) return " " + opt->get_option_text();
    if (opt->get_expected_max() == 0) return "";  // a flag
    std::string value = placeholder(opt);
    if (opt->get_delimiter() == ',') value += ",...";
    else if (opt->get_expected_max() == CLI::detail::expected_max_vector_size) value += " ...";
    else
      for (int k = 1; k < opt->get_expected_min(); ++k) value += " " + placeholder(opt);
    return " " + value + (opt->get_required() ? " REQUIRED" : "");
  }
  std::string make_option_desc(const CLI::Option* opt) const override {
    std::string d = opt->get_description();
    const std::string type = opt->get_type_name(), extra = type.find(':') == std::string::npos
                                                                ? std::string()
                                                                : type.substr(type.find(':') + 1);
    if (const size_t in = extra.find(" in ["); in != std::string::npos) {  // CLI::Range: "INT in [lo - hi]"
      std::string range = extra.substr(in + 5);
      range = range.substr(0, range.find(']'));
      if (const size_t dash = range.find(" - "); dash != std::string::npos)
        range = range.substr(0, dash) + ".." + range.substr(dash + 3);
      d += " [" + range + "]";
    } else if (!extra.empty() && extra[0] == '{') {  // CLI::IsMember: "{a,b}"
      d += " (one of: " + extra.substr(1, extra.find('}') - 1) + ")";
    }
    std::string def = opt->get_expected_max() == 0 ? std::string() : opt->get_default_str();
    if (def.size() >= 2 && def.front() == '[' && def.back() == ']') def = def.substr(1, def.size() - 2);
    if (!def.empty() && d.find("default") == std::string::npos) d += " (default: " + def + ")";
    return d;
  }

 private:
  /// The value's kind without validator text: "INT", "FLOAT", "TEXT" or the option's own name for it.
  static std::string placeholder(const CLI::Option* opt) {
    std::string t = opt->get_type_name();
    t = t.substr(0, t.find(':'));
    return t.empty() ? "VALUE" : t;
  }
};

/// Installs the shared help layout and --version on `app`; call it before
/// adding options. With `showDefaults` every option's default value is
/// printed in --help (the raytracer states its defaults in words instead:
/// its zero values mean "off").
inline void setupCommandLine(CLI::App& app, const std::string& program, bool showDefaults = true) {
  app.formatter(std::make_shared<HelpFormatter>());
  app.get_formatter()->column_width(34);
  app.set_version_flag("--version", versionLine(program), "print the git revision and build type, then exit");
  app.option_defaults()->always_capture_default(showDefaults);
}

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
  if (const std::string kind = aliaslab::specialFileKind(path); !kind.empty())  // a FIFO would block the reader
    return path + ": is " + kind + ", not a regular file: a --config file is read from a regular file";
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
/// otherwise the exit code: 0 after printing --help or --version, 2 after
/// printing a usage error as "<program>: <message>" (CLI11's own codes are
/// not used, so every front end exits 2 for bad options).
/// The first problem (checkConfigFile) of a --config file that argv names, or "" (none named, or none found).
inline std::string commandLineConfigProblem(const CLI::App& app, int argc, char** argv) {
  if (const CLI::Option* config = app.get_config_ptr())
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      std::string file;
      for (const std::string& name : config->get_lnames())
        if (a == "--" + name && i + 1 < argc) file = argv[i + 1];
        else if (a.rfind("--" + name + "=", 0) == 0) file = a.substr(name.size() + 3);
      if (file.empty()) continue;
      if (std::string problem = checkConfigFile(app, file); !problem.empty()) return problem;
    }
  return {};
}

inline int parseCommandLine(CLI::App& app, int argc, char** argv, const char* program) {
  if (const std::string problem = commandLineConfigProblem(app, argc, argv); !problem.empty()) {
    std::fprintf(stderr, "%s: --config: %s\n", program, problem.c_str());
    return 2;
  }
  try {
    app.parse(argc, argv);
    refuseNonFiniteNumbers(app);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "%s: %s\nRun with --help for the options.\n", program, e.what());
    return 2;
  }
  return -1;
}

}  // namespace aliaslab
