// The shared front end of the experiments (experiments/common/front_end.h):
// the library's neutral keys become each program's flags in one place, "{key}"
// placeholders in messages too, and every exception becomes the program's
// message and exit code.
#include <gtest/gtest.h>

#include <stdexcept>

#include "common/front_end.h"  // experiments/common: the front ends' library (aliaslab_frontend)
#include "core/error.h"

using namespace aliaslab;

namespace {
const FrontEnd kProgram{"prog", {{"radius", "--radii"}, {"out", "--out"}, {"grid", "-grid"}}};

std::pair<int, std::string> run(const FrontEnd& p, const std::function<int()>& body) {
  testing::internal::CaptureStderr();
  const int rc = runFrontEnd(p, body);
  return {rc, testing::internal::GetCapturedStderr()};
}
}  // namespace

TEST(FrontEnd, MapsKeysToTheProgramsFlags) {
  EXPECT_EQ(kProgram.flag("radius"), "--radii");
  EXPECT_EQ(kProgram.flag("grid"), "-grid");
  EXPECT_EQ(kProgram.flag("--radius"), "--radius");  // a dashed key is a flag already (the front end's own)
  EXPECT_EQ(kProgram.flag("--images"), "--images");  // not in the map: as given (the front end's own errors)
  EXPECT_EQ(kProgram.flag("seeds"), "seeds");
  EXPECT_EQ(kProgram.message(OptionError("radius", "must be > 0")), "--radii: must be > 0");
  EXPECT_EQ(kProgram.message(FileError("a.csv", "in use: give another {out} or {csv}")),
            "a.csv: in use: give another --out or {csv}");
}

TEST(FrontEnd, PrintsAndExitsAsTheProgramSays) {
  EXPECT_EQ(run(kProgram, [] { return 0; }), std::make_pair(0, std::string()));
  EXPECT_EQ(run(kProgram, []() -> int { throw OptionError("grid", "bad"); }),
            std::make_pair(2, std::string("prog: -grid: bad\n")));
  EXPECT_EQ(run(kProgram, []() -> int { throw FileError("s.txt", "not found"); }),
            std::make_pair(2, std::string("prog: s.txt: not found\n")));
  EXPECT_EQ(run(kProgram, []() -> int { throw std::runtime_error("disk full"); }),
            std::make_pair(1, std::string("prog: failed: disk full\n")));
  const FrontEnd raytracer{"raytracer", {}, 2, 1, 1, "error: "};
  EXPECT_EQ(run(raytracer, []() -> int { throw FileError("s.txt", "not found"); }).first, 1);
  EXPECT_EQ(run(raytracer, []() -> int { throw std::runtime_error("x"); }).second, "raytracer: error: x\n");
}

TEST(FrontEnd, RekeyedErrorsNameTheCallersParameter) {
  try {
    rekeyOption("sampler", "samplers", [] { throw OptionError("sampler", "unknown"); });
    ADD_FAILURE();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.key(), "samplers");
    EXPECT_EQ(e.message(), "unknown");
    EXPECT_STREQ(e.what(), "samplers: unknown");
  }
  EXPECT_THROW(rekeyOption("sampler", "samplers", [] { throw OptionError("spp", "x"); }), OptionError);
  try {  // the library's keys have no dashes: a dashed key is a front end's flag, passed on as it is
    rekeyOption("sampler", "samplers", [] { throw OptionError("--sampler", "x"); });
    ADD_FAILURE();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.key(), "--sampler");
  }
}
