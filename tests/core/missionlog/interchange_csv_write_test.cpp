#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <sstream>

#include "common/input_error.h"
#include "missionlog/interchange_csv.h"

namespace auv {
namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();

bool sameBits(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::memcmp(&a, &b, sizeof a) == 0;
}

MissionLog awkwardLog() {
  MissionLog log;
  log.metadata = {{"vehicle", "hugin1000"},
                  {"start", "2026-05-14T08:12:00Z"},
                  {"roll_mass_sign", "positive = starboard down"},
                  {"", "free comment"}};
  for (int i = 0; i < 1000; ++i) log.time.push_back(i * 0.1 + 1e-7);  // not short decimals
  LogChannel& depth = log.addChannel("depth", "m");
  LogChannel& pitch = log.addChannel("pitch_cmd", "deg");
  LogChannel& flag = log.addChannel("dive_number", "1");
  LogChannel& nounit = log.addChannel("note_value", "");
  for (int i = 0; i < 1000; ++i) {
    depth.values[i] = i % 7 == 0 ? kNaN : 100.0 / 3.0 + i * 1e-9;
    if (i % 10 == 0) pitch.values[i] = -std::sqrt(2.0) * i;
    flag.values[i] = i / 100;
    nounit.values[i] = i % 2 ? 1e-300 * i : -1.2345678901234567e25;
  }
  depth.values[1] = -0.0;
  return log;
}

void expectIdentical(const MissionLog& a, const MissionLog& b) {
  ASSERT_EQ(a.rowCount(), b.rowCount());
  for (std::size_t i = 0; i < a.rowCount(); ++i)
    ASSERT_TRUE(sameBits(a.time[i], b.time[i])) << "row " << i;
  ASSERT_EQ(a.channels.size(), b.channels.size());
  for (std::size_t c = 0; c < a.channels.size(); ++c) {
    EXPECT_EQ(a.channels[c].name, b.channels[c].name);
    EXPECT_EQ(a.channels[c].unit, b.channels[c].unit);
    for (std::size_t i = 0; i < a.rowCount(); ++i)
      ASSERT_TRUE(sameBits(a.channels[c].values[i], b.channels[c].values[i]))
          << a.channels[c].name << " row " << i << ": " << a.channels[c].values[i] << " vs "
          << b.channels[c].values[i];
  }
  ASSERT_EQ(a.metadata.size(), b.metadata.size());
  for (std::size_t k = 0; k < a.metadata.size(); ++k) {
    EXPECT_EQ(a.metadata[k].key, b.metadata[k].key);
    EXPECT_EQ(a.metadata[k].value, b.metadata[k].value);
  }
}
}  // namespace

TEST(InterchangeCsvWrite, RoundTripIsBitExact) {
  const MissionLog log = awkwardLog();
  const auto path = std::filesystem::temp_directory_path() /
                    ("missionlog_roundtrip_" + std::to_string(::getpid()) + ".csv");
  writeInterchangeCsv(log, path);
  ReadReport r;
  const MissionLog back = readInterchangeCsv(path, {}, r);
  // The only note: the unit-less extra column is fine, nothing else to say.
  EXPECT_TRUE(r.clean()) << r.summary();
  expectIdentical(log, back);
  // Writing what was read gives the same bytes again.
  std::ostringstream first, second;
  writeInterchangeCsv(log, first);
  writeInterchangeCsv(back, second);
  EXPECT_EQ(first.str(), second.str());
  std::filesystem::remove(path);
}

TEST(InterchangeCsvWrite, LayoutFollowsTheFormat) {
  MissionLog log;
  log.metadata = {{"vehicle", "slocum-g2"}};
  log.time = {0.0, 0.5, 1.25};
  LogChannel& d = log.addChannel("depth", "m");
  d.values = {1.5, kNaN, 2.0};
  std::ostringstream out;
  writeInterchangeCsv(log, out);
  EXPECT_EQ(out.str(),
            "# vehicle: slocum-g2\n"
            "time [s],depth [m]\n"
            "0,1.5\n"
            "0.5,\n"
            "1.25,2\n");
}

TEST(InterchangeCsvWrite, RefusesWhatWouldNotReadBack) {
  auto base = [] {
    MissionLog log;
    log.time = {0.0, 1.0};
    log.addChannel("depth", "m").values = {1.0, 2.0};
    return log;
  };
  std::ostringstream out;
  {
    MissionLog log = base();
    log.channels[0].name = "depth,m";
    EXPECT_THROW(writeInterchangeCsv(log, out), InputError);
  }
  {
    MissionLog log = base();
    log.metadata.push_back({"start:time", "x"});
    EXPECT_THROW(writeInterchangeCsv(log, out), InputError);
  }
  {
    MissionLog log = base();
    log.metadata.push_back({"note", "two\nlines"});
    EXPECT_THROW(writeInterchangeCsv(log, out), InputError);
  }
  {
    MissionLog log = base();
    log.time = {1.0, 1.0};
    EXPECT_THROW(writeInterchangeCsv(log, out), InputError);
  }
  {
    MissionLog log = base();
    log.channels[0].values.pop_back();
    EXPECT_THROW(writeInterchangeCsv(log, out), InputError);
  }
  {
    MissionLog log = base();
    log.channels[0].values[1] = std::numeric_limits<double>::infinity();
    EXPECT_THROW(writeInterchangeCsv(log, out), InputError);
  }
  EXPECT_TRUE(out.str().empty());  // nothing half-written
  EXPECT_THROW(writeInterchangeCsv(base(), std::filesystem::path("/nonexistent_dir/x.csv")), InputError);
}

}  // namespace auv
