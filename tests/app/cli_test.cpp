#include <gtest/gtest.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace auv {
using testing::runCli;

TEST(Cli, VersionAndHelp) {
  const auto v = runCli("--version");
  EXPECT_EQ(v.code, 0);
  EXPECT_NE(v.out.find("auvballast 0."), std::string::npos);
  const auto h = runCli("--help");
  EXPECT_EQ(h.code, 0);
  EXPECT_NE(h.out.find("vehicles"), std::string::npos);
}

TEST(Cli, VehiclesListsHugin) {
  const auto r = runCli("vehicles");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("hugin1000"), std::string::npos);
  const auto j = runCli("vehicles --json -");
  ASSERT_EQ(j.code, 0) << j.err;
  const auto list = nlohmann::json::parse(j.out);
  bool found = false;
  for (const auto& v : list) found |= v["id"] == "hugin1000" && v["points"] == 4;
  EXPECT_TRUE(found);
}

TEST(Cli, UnknownSubcommandIsExitCode2) {
  const auto r = runCli("fly-to-the-moon");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("auvballast:"), std::string::npos);
}

TEST(Cli, ConvertWritesInterchangeCsvThatReadsBack) {
  // A Slocum ASCII fixture becomes interchange CSV with the same row count.
  const std::string in = std::string(AUV_TEST_DATA_DIR) + "/missionlog/slocum_shallow.asc";
  const std::string out = ::testing::TempDir() + std::to_string(::getpid()) + "_converted.csv";
  const auto r = runCli("convert --log " + in + " --out " + out);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("rows"), std::string::npos);
  const auto back = runCli("convert --log " + out + " --out " + out + ".2.csv");
  ASSERT_EQ(back.code, 0) << back.err;
  EXPECT_EQ(r.out.substr(r.out.find(": ") + 2, r.out.find(" rows") - r.out.find(": ") - 2),
            back.out.substr(back.out.find(": ") + 2, back.out.find(" rows") - back.out.find(": ") - 2));
  const auto bad = runCli("convert --log /nonexistent.csv --out " + out);
  EXPECT_EQ(bad.code, 2);
}

}  // namespace auv
