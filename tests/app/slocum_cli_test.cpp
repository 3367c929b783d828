// auvballast convert on native Slocum binary files: `--cache-dir` is where a
// file whose sensor list is factored out finds its cache, and without it the
// error names the CRC, the folders searched and the flag.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "cli_runner.h"

namespace auv {
namespace {
using testing::runCli;

const std::string kDir = std::string(AUV_TEST_DATA_DIR) + "/missionlog/slocum";

TEST(SlocumCli, ConvertFindsTheCacheInTheCacheDir) {
  ::setenv("XDG_CACHE_HOME", (::testing::TempDir() + "slocum-cli-cache").c_str(), 1);
  const std::string out = ::testing::TempDir() + std::to_string(::getpid()) + "_sci.csv";
  const auto r = runCli("convert --log " + kDir + "/unit_042-sci.ecd --cache-dir " + kDir + "/ccc --out " + out);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find(": 3 rows, 4 channels (read as Slocum binary)"), std::string::npos) << r.out;
  const auto missing = runCli("convert --log " + kDir + "/unit_042-sci.ecd --out " + out);
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("unit_042-sci.ecd:13: sensor_list_crc:"), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("CRC 5c1e0b0e"), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("looked in: " + kDir + ", "), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("--cache-dir DIR"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace auv
