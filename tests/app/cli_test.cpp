#include <gtest/gtest.h>

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

}  // namespace auv
