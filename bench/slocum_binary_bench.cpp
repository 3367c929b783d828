// Slocum binary decode speed (target >= 200 MB/s of input on one core) and
// the import of a whole raw mission folder into mission logs, in MB/s of
// input. Decode = header, sensor list or cache, known bytes, every data cycle
// to per-sensor values (detail::decodeSlocumFile); import = the whole reader
// (channels, units, tidying, one MissionLog per file).
// Usage: slocum_binary_bench [raw-folder]   (default: ../shared comet raw
// folder when present; a generated 64 MB file is always measured)
#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "missionlog/detail/slocum_file.h"
#include "missionlog/detail/slocum_lz4.h"
#include "missionlog/slocum_binary_reader.h"
#include "slocum_test_writer.h"

namespace fs = std::filesystem;

namespace {

// CPU time of this thread: the figure is "MB/s on one core" even when the
// machine is shared (wall time is printed too, for an idle machine).
double cpuNow() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A flight computer's file: 400 sensors of every size; each cycle writes the
// time, a third of the sensors with new values and a third "same as before".
std::string generated(double targetBytes) {
  auv::test::SlocumWriterFile f;
  f.sensors.push_back({"m_present_time", "timestamp", 8});
  const int sizes[] = {4, 4, 8, 1, 2, 4};
  for (int k = 1; k < 400; ++k) f.sensors.push_back({"u_bench_" + std::to_string(k), "nodim", sizes[k % 6]});
  const std::size_t n = f.sensors.size();
  std::size_t bytes = 0;
  for (std::size_t c = 0; static_cast<double>(bytes) < targetBytes; ++c) {
    auv::test::SlocumWriterCycle cy;
    cy.state.resize(n);
    cy.value.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      cy.state[k] = k == 0 || c == 0 ? 2 : static_cast<int>((k * 7 + c * 3) % 3);
      cy.value[k] = k == 0 ? 1.7e9 + 4.0 * static_cast<double>(c) : std::sin(static_cast<double>(k + c)) * 100.0;
      if (cy.state[k] == 2) bytes += static_cast<std::size_t>(f.sensors[k].bytes);
    }
    bytes += 1 + (n + 3) / 4;
    f.cycles.push_back(std::move(cy));
  }
  return auv::test::writeSlocumBinary(f);
}

// Best of `reps` runs of `f` over `bytes` of input, MB/s of CPU time.
template <class F>
double rate(double bytes, int reps, F&& f) {
  double best = 1e300;
  for (int r = 0; r < reps; ++r) {
    const double t0 = cpuNow();
    f();
    best = std::min(best, cpuNow() - t0);
  }
  return bytes / 1e6 / best;
}

}  // namespace

int main(int argc, char** argv) {
  auv::ReadOptions o;
  o.slocum_user_cache = false;

  const std::string big = generated(64e6);
  std::size_t cycles = 0;
  const double mbs = rate(static_cast<double>(big.size()), 5, [&] {
    cycles = auv::detail::decodeSlocumFile(big, "/nonexistent/bench.dbd", o).cycles.cycles;
  });
  std::printf("generated .dbd, %.1f MB, %zu cycles x 400 sensors: decode %.0f MB/s (target >= 200)\n",
              static_cast<double>(big.size()) / 1e6, cycles, mbs);
  const std::string packed = auv::detail::slocumLz4Compress(big);
  const double mbsLz4 = rate(static_cast<double>(packed.size()), 5, [&] {
    cycles = auv::detail::decodeSlocumFile(packed, "/nonexistent/bench.dcd", o).cycles.cycles;
  });
  std::printf("same, LZ4 .dcd, %.1f MB: decode %.0f MB/s of compressed input (%.0f MB/s of the data it holds)\n",
              static_cast<double>(packed.size()) / 1e6, mbsLz4,
              mbsLz4 * static_cast<double>(big.size()) / static_cast<double>(packed.size()));

  const fs::path folder = argc > 1 ? fs::path(argv[1])
                                   : fs::path(AUV_SHARED_DIR) / "data" / "real" / "slocum-comet-baltic-2016" / "raw";
  std::vector<fs::path> files;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string ext = it->path().extension().string();
    if (ext.size() == 4 && (ext[2] == 'b' || ext[2] == 'c') && ext[3] == 'd') files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    std::printf("no raw Slocum folder at %s: folder figures skipped\n", folder.string().c_str());
    return 0;
  }
  std::vector<std::string> contents;
  double total = 0;
  for (const auto& p : files) {
    contents.push_back(slurp(p));
    total += static_cast<double>(contents.back().size());
  }
  const double decodeAll = rate(total, 5, [&] {
    for (std::size_t i = 0; i < files.size(); ++i) auv::detail::decodeSlocumFile(contents[i], files[i], o);
  });
  std::size_t rows = 0;
  const double importAll = rate(total, 3, [&] {
    rows = 0;
    for (const auto& p : files) {
      auv::ReadReport r;
      rows += auv::readSlocumBinary(p, o, r).rowCount();
    }
  });
  std::printf("raw folder %s: %zu files, %.2f MB: decode %.0f MB/s, import (files -> mission logs, %zu rows) %.0f MB/s\n",
              folder.string().c_str(), files.size(), total / 1e6, decodeAll, rows, importAll);
  return 0;
}
