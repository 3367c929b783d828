// Attitude units in the interchange CSV, with the rule the vendor readers use
// (detail/attitude_sanity.h): degrees written under a [rad] header would give
// a 163 deg roll and +4682 kg (issue 15) and are refused naming the column
// and the fix; radians under [deg] in a log that dives are warned about;
// correct units pass without a word.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/input_error.h"
#include "missionlog/interchange_csv.h"

namespace auv {
namespace {

// A 400 s dive from 5 to 65 m with a pitch of about -10..+10 deg, written in
// `pitch_unit` with the values `pitch_scale` times the degrees.
std::string dive(const char* pitch_unit, double pitch_scale) {
  std::string s = "# vehicle: hugin1000\ntime [s],depth [m],pitch [" + std::string(pitch_unit) + "]\n";
  char buf[96];
  for (int t = 0; t < 400; ++t) {
    std::snprintf(buf, sizeof buf, "%d,%.2f,%.5f\n", t, 35.0 + 30.0 * std::sin(t / 60.0),
                  pitch_scale * 10.0 * std::cos(t / 60.0));
    s += buf;
  }
  return s;
}

bool mentions(const ReadReport& r, const std::string& what) {
  for (const auto& p : r.problems)
    if (p.text().find(what) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(AttitudeUnits, DegreesUnderARadHeaderAreRefusedWithTheFix) {
  ReadReport r;
  try {
    parseInterchangeCsv(dive("rad", 1.0), "deg_as_rad.csv", {}, r);
    FAIL() << "degrees under [rad] must be refused";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(e.field(), "pitch");
    EXPECT_EQ(e.where().file, "deg_as_rad.csv");
    EXPECT_EQ(e.where().line, 2);  // the header line
    EXPECT_NE(m.find("beyond +-90 deg"), std::string::npos) << m;
    EXPECT_NE(m.find("write `pitch [deg]`"), std::string::npos) << m;
  }
}

TEST(AttitudeUnits, RadiansUnderADegHeaderInADiveAreWarnedAbout) {
  ReadReport r;
  const MissionLog log = parseInterchangeCsv(dive("deg", M_PI / 180.0), "rad_as_deg.csv", {}, r);
  EXPECT_EQ(log.rowCount(), 400u);
  EXPECT_TRUE(mentions(r, "looks like radians")) << r.summary();
  EXPECT_TRUE(mentions(r, "pitch [rad]")) << r.summary();
}

TEST(AttitudeUnits, CorrectUnitsPassSilently) {
  ReadReport deg, rad;
  parseInterchangeCsv(dive("deg", 1.0), "ok_deg.csv", {}, deg);
  const MissionLog log = parseInterchangeCsv(dive("rad", M_PI / 180.0), "ok_rad.csv", {}, rad);
  EXPECT_TRUE(deg.clean()) << deg.summary();
  EXPECT_TRUE(rad.clean()) << rad.summary();
  EXPECT_NEAR(log.channel("pitch").values[0], 10.0, 1e-3);  // converted to degrees
}

}  // namespace auv
