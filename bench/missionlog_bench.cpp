// Interchange CSV read speed on a 24 h, 10 Hz log (864,000 rows x 13 columns,
// ~55 MB), the size issue 3 sets the target for (>= 300 MB/s, one thread).
// Usage: missionlog_bench [existing.csv]   (default: generate a temp file)
#include <sys/resource.h>

#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "analysis/mission_analysis.h"
#include "missionlog/interchange_csv.h"
#include "vehicle/vehicle_catalog.h"

namespace {

double peakRssMb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // Linux: kB
}

void put(std::string& s, double v, int decimals) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  s.append(buf, r.ptr);
}

// A plausible AUV mission: yo-free depth legs, slow heading changes, a CTD at
// 1 Hz (empty cells 9 rows in 10) and an altimeter that loses the bottom.
void generate(const std::filesystem::path& path, long rows) {
  std::ofstream out(path, std::ios::binary);
  std::string s =
      "# vehicle: hugin1000\n# mission: bench-24h-10hz\n# start: 2026-05-14T08:12:00Z\n"
      "time [s],depth [m],depth_cmd [m],altitude [m],pitch [deg],pitch_cmd [deg],roll [deg],"
      "heading [deg],speed [m/s],prop_rpm [rpm],elevator [deg],rudder [deg],temperature [degC]\n";
  for (long i = 0; i < rows; ++i) {
    const double t = 0.1 * static_cast<double>(i);
    const double cmd = 50.0 + 25.0 * std::floor(std::fmod(t / 1800.0, 4.0));
    put(s, t, 1);
    s += ',';
    put(s, cmd + 0.8 * std::sin(t / 37.0), 2);
    s += ',';
    put(s, cmd, 0);
    s += ',';
    const double alt = 180.0 - cmd + 5.0 * std::sin(t / 300.0);
    if (alt < 120.0) put(s, alt, 2);
    s += ',';
    put(s, 1.5 * std::sin(t / 23.0), 2);
    s += ',';
    put(s, 0.0, 0);
    s += ',';
    put(s, 0.4 * std::sin(t / 7.0), 2);
    s += ',';
    put(s, std::fmod(90.0 + t / 60.0, 360.0), 1);
    s += ',';
    put(s, 2.0 + 0.05 * std::sin(t / 11.0), 2);
    s += ',';
    put(s, 160.0, 0);
    s += ',';
    put(s, -2.0 + std::sin(t / 19.0), 2);
    s += ',';
    put(s, 0.3 * std::sin(t / 5.0), 2);
    s += ',';
    if (i % 10 == 0) put(s, 8.0 + 0.01 * std::sin(t / 900.0), 3);
    s += '\n';
    if (s.size() > (1 << 20)) {
      out.write(s.data(), static_cast<std::streamsize>(s.size()));
      s.clear();
    }
  }
  out.write(s.data(), static_cast<std::streamsize>(s.size()));
}

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  fs::path path;
  bool temp = false;
  if (argc > 1) {
    path = argv[1];
  } else {
    path = fs::temp_directory_path() / ("missionlog_bench_" + std::to_string(::getpid()) + ".csv");
    temp = true;
    const auto g0 = std::chrono::steady_clock::now();
    generate(path, 864000);
    std::printf("generated %s in %.2f s\n", path.c_str(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - g0).count());
  }
  const double mb = static_cast<double>(fs::file_size(path)) / 1e6;
  const double rssBefore = peakRssMb();
  double best = 1e30;
  std::size_t rows = 0, channels = 0;
  double rssAfterFirst = 0.0;
  for (int run = 0; run < 5; ++run) {
    auv::ReadReport report;
    const auto t0 = std::chrono::steady_clock::now();
    const auv::MissionLog log = auv::readInterchangeCsv(path, auv::ReadOptions{}, report);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    best = std::min(best, s);
    rows = log.rowCount();
    channels = log.channels.size();
    if (run == 0) {
      rssAfterFirst = peakRssMb();
      std::printf("first read: %.3f s, %.0f MB/s; %zu problems\n", s, mb / s,
                  static_cast<std::size_t>(report.totalProblems()));
    }
  }
  std::printf("file: %.1f MB, %zu rows x %zu channels + time\n", mb, rows, channels);
  std::printf("read (best of 5): %.3f s, %.0f MB/s\n", best, mb / best);
  std::printf("peak RSS: %.1f MB before reading, %.1f MB after the first read (%.1f MB of columns)\n",
              rssBefore, rssAfterFirst, static_cast<double>(rows * (channels + 1) * 8) / 1e6);
  {
    auv::ReadReport report;
    const auv::MissionLog log = auv::readInterchangeCsv(path, auv::ReadOptions{}, report);
    const fs::path out = path.string() + ".out.csv";
    const auto t0 = std::chrono::steady_clock::now();
    auv::writeInterchangeCsv(log, out);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("write: %.3f s, %.0f MB/s\n", s, static_cast<double>(fs::file_size(out)) / 1e6 / s);
    fs::remove(out);
  }
  {
    // The target: import + full post-mission analysis of the day-long
    // log in < 0.6 s with peak RSS < 250 MB.
    const auv::VehicleProfile v = auv::VehicleCatalog(std::string(AUV_RESOURCE_DIR) + "/vehicles").load("hugin1000");
    double best_total = 1e30, best_analysis = 1e30;
    std::size_t segments = 0;
    for (int run = 0; run < 3; ++run) {
      const auto t0 = std::chrono::steady_clock::now();
      auv::ReadReport report;
      const auv::MissionLog log = auv::readInterchangeCsv(path, auv::ReadOptions{}, report);
      const auto t1 = std::chrono::steady_clock::now();
      const auv::analysis::AnalysisReport r = auv::analysis::analyzeMission(log, v);
      const auto t2 = std::chrono::steady_clock::now();
      best_total = std::min(best_total, std::chrono::duration<double>(t2 - t0).count());
      best_analysis = std::min(best_analysis, std::chrono::duration<double>(t2 - t1).count());
      segments = r.segments.size();
    }
    std::printf("import + analysis (best of 3): %.3f s (analysis %.3f s, %zu segments); peak RSS %.1f MB\n",
                best_total, best_analysis, segments, peakRssMb());
  }
  if (temp) fs::remove(path);
  return 0;
}
