// core/gzip.h: members written by zlib read back by gzip(1) (an independent decoder) and the other way round,
// several members read as one text, and a file cut anywhere inside its last member read as the members before it
// (what a killed append leaves), told apart from damaged data.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/gzip.h"
#include "support/run_process.h"
#include "support/scratch_dir.h"

namespace fs = std::filesystem;
using namespace aliaslab;

namespace {
fs::path dir() { return aliaslab::testing::scratchDir("aliaslab_gzip_test"); }

void writeBytes(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
}

// Text that compresses well but not trivially: CSV-like lines.
std::string sampleText(int lines, int salt) {
  std::string t;
  for (int i = 0; i < lines; ++i)
    t += "scene" + std::to_string(i % 7) + ",jittered," + std::to_string(i * salt) + ",0.25," +
         std::to_string((i * 2654435761u + salt) % 100000) + "\n";
  return t;
}
}  // namespace

TEST(Gzip, NamesEndingInGzAreCompressed) {
  EXPECT_TRUE(isGzipPath("a/study.csv.gz"));
  EXPECT_FALSE(isGzipPath("a/study.csv"));
  EXPECT_FALSE(isGzipPath(".gz"));
  EXPECT_EQ(withoutGzipSuffix("a/study.csv.gz"), "a/study.csv");
  EXPECT_EQ(withoutGzipSuffix("a/study.csv"), "a/study.csv");
}

TEST(Gzip, SeveralMembersAreReadAsOneTextByGzipAndByUs) {
  const std::string a = sampleText(500, 3), b = sampleText(40, 5), c = "last line\n";
  const std::string bytes = gzipMember(a) + gzipMember(b) + gzipMember(c);
  ASSERT_TRUE(isGzipData(bytes));
  const Gunzipped g = gunzipMembers(bytes);
  EXPECT_EQ(g.text, a + b + c);
  EXPECT_EQ(g.completeBytes, bytes.size());
  EXPECT_EQ(g.damage, "");
  // gzip(1) reads the concatenated members as the same text
  const fs::path gz = dir() / "members.gz", out = dir() / "members.out";
  writeBytes(gz, bytes);
  ASSERT_EQ(std::system(("gzip -dc " + gz.string() + " > " + out.string()).c_str()), 0);
  EXPECT_EQ(aliaslab::testing::readText(out.string()), a + b + c);
  // and we read what gzip -9 -n writes
  const fs::path plain = dir() / "plain.txt";
  writeBytes(plain, a);
  ASSERT_EQ(std::system(("gzip -9 -n -k -f " + plain.string()).c_str()), 0);
  EXPECT_EQ(readTextMaybeGzip(plain.string() + ".gz", false), a);
  EXPECT_EQ(readTextMaybeGzip(plain.string(), false), a);  // a plain file is read as it is
}

TEST(Gzip, TheSameTextGivesTheSameBytes) {
  const std::string t = sampleText(300, 11);
  EXPECT_EQ(gzipMember(t), gzipMember(t));
  EXPECT_LT(gzipMember(t).size(), t.size() / 2);
  EXPECT_EQ(gunzipMembers(gzipMember("")).text, "");
}

TEST(Gzip, ALastMemberCutAnywhereLeavesTheMembersBeforeIt) {
  const std::string a = sampleText(200, 2), b = sampleText(200, 9);
  const std::string first = gzipMember(a), second = gzipMember(b);
  const std::string bytes = first + second;
  for (size_t cut = first.size() + 1; cut < bytes.size(); cut += 7) {
    const Gunzipped g = gunzipMembers(bytes.substr(0, cut));
    ASSERT_EQ(g.text, a) << "cut at " << cut;
    EXPECT_EQ(g.completeBytes, first.size()) << "cut at " << cut;
    EXPECT_TRUE(g.cutShort) << "cut at " << cut << ": " << g.damage;
    EXPECT_NE(g.damage, "");
  }
  // a reader that allows a torn tail drops it; one that does not names the file
  const fs::path p = dir() / "torn.csv.gz";
  writeBytes(p, bytes.substr(0, bytes.size() - 5));
  EXPECT_EQ(readTextMaybeGzip(p.string(), true), a);
  try {
    readTextMaybeGzip(p.string(), false);
    ADD_FAILURE() << "a torn member was accepted";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("torn.csv.gz"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cut short"), std::string::npos) << e.what();
  }
}

TEST(Gzip, DamagedDataIsNotTakenForACutMember) {
  const std::string a = sampleText(200, 4);
  std::string bytes = gzipMember(a) + gzipMember(a);
  bytes[bytes.size() / 2 + 40] ^= 0x55;  // inside the second member's compressed data
  const Gunzipped g = gunzipMembers(bytes);
  EXPECT_EQ(g.text, a);
  EXPECT_FALSE(g.cutShort) << g.damage;
  EXPECT_NE(g.damage, "");
  // plain text after a member is not a member either
  const Gunzipped h = gunzipMembers(gzipMember(a) + "scene,width\n");
  EXPECT_FALSE(h.cutShort);
  EXPECT_NE(h.damage, "");
}

TEST(Gzip, WritesCompressOnlyNamesEndingInGz) {
  const std::string t = sampleText(50, 1);
  writeTextMaybeGzip((dir() / "w.csv").string(), t);
  writeTextMaybeGzip((dir() / "w.csv.gz").string(), t);
  EXPECT_EQ(aliaslab::testing::readText((dir() / "w.csv").string()), t);
  EXPECT_TRUE(isGzipData(aliaslab::testing::readText((dir() / "w.csv.gz").string())));
  EXPECT_EQ(readTextMaybeGzip((dir() / "w.csv.gz").string(), false), t);
}
