#include "missionlog/detail/slocum_lz4.h"

#include <lz4.h>

#include "common/input_error.h"

namespace auv::detail {
namespace {

// Slocum files are at most a few MB; an LZ4 stream that claims far more is
// damage or an attack on memory, not a glider file.
constexpr std::size_t kMaxDecompressed = std::size_t{256} << 20;

std::size_t blockLength(std::string_view data, std::size_t at) {
  return (static_cast<std::size_t>(static_cast<unsigned char>(data[at])) << 8) |
         static_cast<unsigned char>(data[at + 1]);
}

}  // namespace

bool slocumLz4StartsWith(std::string_view head, std::string_view prefix) {
  if (head.size() < 3) return false;
  const std::size_t n = blockLength(head, 0);
  if (n == 0) return false;
  const std::size_t avail = std::min(n, head.size() - 2);
  char out[256];
  const int want = static_cast<int>(std::min(prefix.size(), sizeof out));
  // Partial decoding stops once `want` bytes are out, so a block cut off by
  // the sniffing window still answers.
  const int got = LZ4_decompress_safe_partial(head.data() + 2, out, static_cast<int>(avail), want, sizeof out);
  return got >= want && std::string_view(out, static_cast<std::size_t>(want)) == prefix.substr(0, static_cast<std::size_t>(want));
}

std::string slocumLz4Decompress(std::string_view data, const std::string& file) {
  std::string out;
  out.reserve(data.size() * 3);
  std::size_t at = 0;
  while (at < data.size()) {
    if (data.size() - at < 2)
      throw InputError("lz4", "the file ends inside a block length (byte " + std::to_string(at) + ")",
                       "the compressed file is truncated; copy it from the glider again", {file, 0, 0});
    const std::size_t n = blockLength(data, at);
    if (n == 0 || n > data.size() - at - 2)
      throw InputError("lz4",
                       "block at byte " + std::to_string(at) + " claims " + std::to_string(n) + " bytes, " +
                           std::to_string(data.size() - at - 2) + " remain",
                       "the compressed file is truncated or damaged; copy it from the glider again", {file, 0, 0});
    const std::size_t base = out.size();
    if (base > kMaxDecompressed)
      throw InputError("lz4", "the blocks up to byte " + std::to_string(at) + " decompress to more than 256 MiB",
                       "this is not a compressed Slocum file (they hold a few MB)", {file, 0, 0});
    out.resize(base + kSlocumLz4BlockMax);
    const int got = LZ4_decompress_safe(data.data() + at + 2, out.data() + base, static_cast<int>(n),
                                        static_cast<int>(kSlocumLz4BlockMax));
    if (got < 0)
      throw InputError("lz4", "block at byte " + std::to_string(at) + " is not a valid LZ4 block (or holds more than 32 KiB)",
                       "the compressed file is damaged; copy it from the glider again", {file, 0, 0});
    out.resize(base + static_cast<std::size_t>(got));
    at += 2 + n;
  }
  return out;
}

std::string slocumLz4Compress(std::string_view data) {
  std::string out;
  std::string block(static_cast<std::size_t>(LZ4_compressBound(static_cast<int>(kSlocumLz4BlockMax))), '\0');
  for (std::size_t at = 0; at < data.size(); at += kSlocumLz4BlockMax) {
    const std::size_t n = std::min(kSlocumLz4BlockMax, data.size() - at);
    const int c = LZ4_compress_default(data.data() + at, block.data(), static_cast<int>(n), static_cast<int>(block.size()));
    out += static_cast<char>((c >> 8) & 0xFF);
    out += static_cast<char>(c & 0xFF);
    out.append(block.data(), static_cast<std::size_t>(c));
  }
  return out;
}

}  // namespace auv::detail
