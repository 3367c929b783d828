// Whole-mission import speed: readMission on raw mission folders (all files
// of the folder, decompression and merge included), MB/s of input as stored
// on disk, best of 3, one thread. Usage: mission_folder_bench [FOLDER ...]
// (default: the SeaExplorer and Seaglider raw folders in ../shared).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "missionlog/mission_files.h"

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::vector<fs::path> folders;
  for (int i = 1; i < argc; ++i) folders.emplace_back(argv[i]);
  if (folders.empty()) {
    const fs::path real = fs::path(AUV_SHARED_DIR) / "data" / "real";
    folders = {real / "seaexplorer-sea046-calvert-2020" / "raw", real / "seaglider-sg171-bay-of-bengal-2024" / "raw"};
  }
  for (const auto& dir : folders) {
    if (!fs::is_directory(dir)) {
      std::printf("%s: not a folder, skipped\n", dir.c_str());
      continue;
    }
    double bytes = 0;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file()) bytes += static_cast<double>(e.file_size());
    double best = 1e30;
    std::size_t rows = 0, channels = 0;
    long long problems = 0;
    for (int run = 0; run < 3; ++run) {
      auv::ReadReport r;
      const auto t0 = std::chrono::steady_clock::now();
      const auv::MissionLog log = auv::readMission({dir}, {}, r);
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      rows = log.rowCount();
      channels = log.channels.size();
      problems = r.totalProblems();
    }
    std::printf("%s: %.1f MB in %.3f s = %.1f MB/s; %zu rows, %zu channels, %lld problems\n", dir.c_str(), bytes / 1e6,
                best, bytes / 1e6 / best, rows, channels, problems);
  }
  return 0;
}
