#pragma once
// How a log reader is asked to read, and how a reader says it was cancelled.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>

namespace auv {

struct ReadOptions {
  // Called with the fraction of the file consumed (0..1, non-decreasing, 1 at
  // the end). Returning false cancels the read, which then throws
  // ReadCancelled; nothing partial is returned.
  std::function<bool(double fraction)> progress;
  // How many problems of each kind the report keeps in full (all are counted).
  std::size_t max_problems_per_kind = 20;
  // |value| above this (and +-inf) is a fill value or corruption, not a
  // measurement: the cell is treated as not sampled and counted. 1e30 sits
  // below the NetCDF default fill (9.97e36) and far above any physical channel.
  double max_abs_value = 1e30;
  // Read block size; also the longest line a reader accepts (longer lines are
  // skipped and reported). Tests and the fuzzer use small blocks.
  std::size_t block_bytes = std::size_t{4} << 20;
  // Slocum binary files whose sensor list is factored out name a cache file
  // by CRC; it is looked up here first (CLI `--cache-dir`), then next to the
  // file, then in the per-user cache ($XDG_CACHE_HOME/auvballast/slocum-cache).
  std::filesystem::path slocum_cache_dir;
  // Look up and fill the per-user cache (off in the fuzzer, which must not
  // write caches named by random CRCs into the home folder).
  bool slocum_user_cache = true;
};

// Thrown when ReadOptions::progress returns false. Not an InputError: the
// file may be fine, the user just stopped reading it.
class ReadCancelled : public std::runtime_error {
 public:
  explicit ReadCancelled(const std::string& file)
      : std::runtime_error("reading " + file + " was cancelled"), file_(file) {}
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

}  // namespace auv
