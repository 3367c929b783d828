// Logger drop-outs of 1 s to 30 days, black box: the simulated HUGIN mission
// of resources/examples/hugin1000_ballast_error.plan.json (2,701 rows at
// 1 Hz, known ballast error in its # truth lines) with rows removed and the
// clock pushed on after each hole. analyze, model-check and simulate --replay
// must all still work (before: model-check refused any gap of ~6 s with
// "depth_m: is not a number"; replay of a 23-day gap took 1.3 GB), the
// analysis must not let a segment run across a gap, its estimate must stay
// with the gap-free one, and memory must follow the rows.
#include <sys/resource.h>
#include <unistd.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace auv {
using testing::runCli;

namespace {

std::string tmp(const std::string& name) { return ::testing::TempDir() + std::to_string(::getpid()) + "_gaps_" + name; }

std::vector<std::string> lines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// Drop-outs: after data row `at`, `missing` rows are removed and the next kept
// row comes `gap_s` after the last kept one (one missing row at 1 Hz: 2 s).
struct Dropout {
  std::size_t at;
  std::size_t missing;
  double gap_s;
};

const std::vector<Dropout> kDropouts = {
    {200, 1, 2.0},        {400, 5, 6.0},       {600, 30, 31.0},     {900, 60, 3600.0},
    {1300, 10, 86400.0},  {1700, 20, 23 * 86400.0}, {2100, 40, 30 * 86400.0}};

// Returns the gapped file and the gaps' [before, after] times.
std::string writeGapped(const std::string& src, std::vector<std::pair<double, double>>& gaps) {
  std::ofstream out(tmp("gapped.csv"));
  std::size_t row = 0, d = 0, skip = 0;
  double shift = 0.0, last_written = 0.0, pending_gap_s = 0.0;
  for (const std::string& l : lines(src)) {
    if (l.empty() || l[0] == '#' || l.rfind("time", 0) == 0) {
      out << l << "\n";
      continue;
    }
    const std::size_t comma = l.find(',');
    const double t = std::stod(l.substr(0, comma));
    if (skip > 0) {
      --skip;
      ++row;
      continue;
    }
    if (pending_gap_s > 0.0) {  // first row after a hole: the clock has moved on by the gap
      shift = last_written + pending_gap_s - t;
      gaps.push_back({last_written, t + shift});
      pending_gap_s = 0.0;
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3f", t + shift);
    out << buf << l.substr(comma) << "\n";
    last_written = t + shift;
    if (d < kDropouts.size() && row == kDropouts[d].at) {
      skip = kDropouts[d].missing;
      pending_gap_s = kDropouts[d].gap_s;
      ++d;
    }
    ++row;
  }
  return tmp("gapped.csv");
}

nlohmann::json json(const std::string& out) { return nlohmann::json::parse(out); }

class Gaps : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    clean_ = new std::string(tmp("clean.csv"));
    const auto r = runCli("simulate --vehicle hugin1000 --plan " + std::string(AUV_RESOURCE_DIR) +
                          "/examples/hugin1000_ballast_error.plan.json --out " + *clean_);
    ASSERT_EQ(r.code, 0) << r.err;
    gaps_ = new std::vector<std::pair<double, double>>();
    gapped_ = new std::string(writeGapped(*clean_, *gaps_));
  }
  static std::string* clean_;
  static std::string* gapped_;
  static std::vector<std::pair<double, double>>* gaps_;
};
std::string* Gaps::clean_ = nullptr;
std::string* Gaps::gapped_ = nullptr;
std::vector<std::pair<double, double>>* Gaps::gaps_ = nullptr;

TEST_F(Gaps, AnalysisEndsSegmentsAtGapsAndKeepsItsEstimate) {
  ASSERT_EQ(gaps_->size(), kDropouts.size());
  const auto clean = runCli("analyze --vehicle hugin1000 --log " + *clean_ + " --installed 7.2,7.2,25.2,25.2 --json -");
  const auto gapped = runCli("analyze --vehicle hugin1000 --log " + *gapped_ + " --installed 7.2,7.2,25.2,25.2 --json -");
  ASSERT_EQ(clean.code, 0) << clean.err;
  ASSERT_EQ(gapped.code, 0) << gapped.err;
  const auto a = json(clean.out), b = json(gapped.out);
  // 2.8 % of the rows are gone: the estimate moves by a fraction of its sigma, not by kilograms.
  ASSERT_TRUE(b["net_buoyancy_kg"].is_number());
  EXPECT_NEAR(b["net_buoyancy_kg"].get<double>(), a["net_buoyancy_kg"].get<double>(),
              std::max(0.2, 3.0 * a["net_buoyancy_sigma_kg"].get<double>()));
  // No segment covers a gap longer than the segmenter's 120 s.
  for (const auto& s : b["segments"]) {
    for (const auto& [before, after] : *gaps_) {
      if (after - before <= 120.0) continue;
      const bool across = s["start_s"].get<double>() < before + 1e-6 && s["end_s"].get<double>() > after - 1e-6;
      EXPECT_FALSE(across) << "segment " << s.dump() << " runs across the gap " << before << " .. " << after;
    }
  }
}

TEST_F(Gaps, ModelCheckWorksAcrossDropouts) {
  const auto r = runCli("model-check --vehicle hugin1000 --log " + *gapped_ + " --installed 7.2,7.2,25.2,25.2 --json -");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = json(r.out);
  EXPECT_TRUE(j.contains("missing_physics"));
  ASSERT_TRUE(j["net_buoyancy_kg"].is_number());
  EXPECT_TRUE(std::isfinite(j["net_buoyancy_kg"].get<double>()));
}

TEST_F(Gaps, ReplayRestartsAfterGapsWithMemoryFollowingTheRows) {
  const std::string out = tmp("replay.csv");
  const auto r = runCli("simulate --vehicle hugin1000 --replay " + *gapped_ + " --out " + out);
  ASSERT_EQ(r.code, 0) << r.err;
  std::size_t in_rows = 0, out_rows = 0;
  for (const auto& l : lines(*gapped_)) in_rows += !l.empty() && l[0] != '#' && l.rfind("time", 0) != 0;
  for (const auto& l : lines(out)) out_rows += !l.empty() && l[0] != '#' && l.rfind("time", 0) != 0;
  EXPECT_EQ(out_rows, in_rows);  // one sample per recorded row, none invented across a gap
  // Peak RSS of every child so far (the CLI runs of this suite): a 23-day gap
  // flown at 20 Hz would need > 1 GB; the rows need a few MB.
  rusage ru{};
  getrusage(RUSAGE_CHILDREN, &ru);
  EXPECT_LT(ru.ru_maxrss, 300L * 1024) << "peak RSS " << ru.ru_maxrss / 1024 << " MB";
}

}  // namespace
}  // namespace auv
