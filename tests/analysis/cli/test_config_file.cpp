// --config reads strict TOML: malformed text, unknown keys and unknown sections are refused with
// exit 2 and a message naming the file, the line and the key (qa.md K02, K09, K21, CX1-CX9); a
// [<subcommand>] section overrides the top level and a later file an earlier one (CX6, K26); a
// top-level key of another subcommand does not break this one (K11); `case` takes --config
// (K27); --print-config writes the effective options as TOML that --config reads back.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

using granbench::testing::CommandResult;
using granbench::testing::run_granbench;
namespace fs = std::filesystem;
using granbench::testing::ScratchDir;

class ConfigFile : public ::testing::Test {
 protected:
  std::string file(const std::string& name, const std::string& text) {
    const std::string path = dir_ / name;
    std::ofstream(path) << text;
    return path;
  }
  CommandResult run(const std::string& args) { return run_granbench(args, "config"); }
  // Exit 2, one line, naming all of `parts`.
  void expect_refused(const std::string& args, const std::vector<std::string>& parts) {
    const auto r = run(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
    for (const auto& p : parts) EXPECT_NE(r.err.find(p), std::string::npos) << p << " in " << r.err;
  }
  double steady_angle(const std::string& args) {
    const auto r = run("steady --json " + args);
    EXPECT_EQ(r.code, 0) << args << "\n" << r.err;
    return r.code == 0 ? nlohmann::json::parse(r.out)["angle"].get<double>() : -1.0;
  }
  const ScratchDir scratch_{"gb_config"};
  const fs::path& dir_ = scratch_.path();
};

TEST_F(ConfigFile, MalformedTomlIsRefusedNamingFileLineAndKey) {
  const auto f = file("bad.toml", "h0 = 0.004\nangle = = 30\n");
  expect_refused("steady --config " + f, {"--config", f + ":2", "'angle'"});
  expect_refused("steady --config " + file("str.toml", "angle = \"30\n"),
                 {"str.toml:1", "unterminated"});
  expect_refused("steady --config " + file("hdr.toml", "[steady\n"), {"hdr.toml:1"});
  expect_refused("steady --config " + file("yaml.toml", "angle: 30\n"), {"yaml.toml:1"});
  expect_refused("steady --config " + file("json.toml", "{\"angle\": 30}\n"), {"json.toml:1"});
  expect_refused("steady --config " + file("bare.toml", "curve = jop\n"),
                 {"bare.toml:1", "'curve'"});
  expect_refused("steady --config " + file("twice.toml", "angle = 30\nangle = 25\n"),
                 {"twice.toml:2", "twice"});
  expect_refused("steady --config " + file("bin.toml", std::string("\x01\x02\xff\xfe", 4)),
                 {"bin.toml:1", "not text"});
}

TEST_F(ConfigFile, UnknownKeysSectionsAndDirectoriesAreRefused) {
  expect_refused("steady --config " + file("key.toml", "h0 = 0.004\nangel = 30\n"),
                 {"key.toml:2", "unknown key 'angel'"});
  expect_refused("steady --config " + file("sec.toml", "[stedy]\nangle = 30\n"),
                 {"sec.toml:1", "unknown section [stedy]"});
  expect_refused("steady --config " + file("seckey.toml", "[steady]\nnx = 30\n"),
                 {"seckey.toml:2", "unknown key 'nx' in [steady]"});
  expect_refused("steady --config " + file("nested.toml", "config = \"x.toml\"\n"),
                 {"nested.toml:1", "'config'"});
  expect_refused("steady --config " + dir_.string(), {"--config", "directory"});
}

TEST_F(ConfigFile, ValuesFollowTomlAndThePrecedenceRules) {
  EXPECT_EQ(steady_angle("--config " + file("u.toml", "angle = 2_5\n")), 25.0);
  EXPECT_EQ(steady_angle("--config " + file("s.toml", "angle = 30\n[steady]\nangle = 25\n")), 25.0);
  EXPECT_EQ(steady_angle("--config " + file("a.toml", "angle = 30\n") + " --config " +
                         file("b.toml", "angle = 25\n")),
            25.0);
  EXPECT_EQ(steady_angle("--config " + file("c.toml", "angle = 25\n") + " --angle 26"), 26.0);
  // A top-level key of `run` does not break `steady`; another subcommand's section is skipped.
  EXPECT_EQ(steady_angle("--config " + file("nx.toml", "nx = 40\nangle = 25\n[run]\nangle = 20\n")),
            25.0);
  // A bad value from a file is named with its place.
  const auto f = file("range.toml", "h0 = 0.004\nangle = 95\n");
  expect_refused("steady --config " + f, {"--angle", f + " line 2"});
}

TEST_F(ConfigFile, CaseTakesConfig) {
  const auto r = run("case --list --config " + file("case.toml", "angle = 25\n"));
  EXPECT_EQ(r.code, 0) << r.err;
}

TEST_F(ConfigFile, PrintConfigWritesTomlThatReadsBack) {
  const auto first = run("steady --angle 25 --curve jop --print-config");
  ASSERT_EQ(first.code, 0) << first.err;
  EXPECT_NE(first.out.find("[steady]"), std::string::npos) << first.out;
  EXPECT_NE(first.out.find("angle = 25"), std::string::npos) << first.out;
  EXPECT_NE(first.out.find("curve = \"jop\""), std::string::npos) << first.out;
  const auto again = run("steady --print-config --config " + file("printed.toml", first.out));
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_EQ(again.out, first.out);
  EXPECT_EQ(steady_angle("--config " + file("printed2.toml", first.out)), 25.0);
  EXPECT_NE(first.out.find("# h0 = 0.004"), std::string::npos) << "defaults shown: " << first.out;
  // Read back, defaults do not count as given: a sweep refuses options of the other model.
  for (const std::string model : {"depthavg", "twod", "both"}) {
    const auto printed = run("sweep --model " + model + " --print-config");
    ASSERT_EQ(printed.code, 0) << printed.err;
    const auto back =
        run("sweep --print-config --config " + file("sweep_" + model + ".toml", printed.out));
    EXPECT_EQ(back.code, 0) << model << ": " << back.err;
    EXPECT_EQ(back.out, printed.out);
  }
}

}  // namespace
