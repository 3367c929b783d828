#pragma once
// The framing of the compressed Slocum files (.dcd .ecd .scd .tcd .mcd .ncd
// and the .ccc caches): a sequence of blocks, each a 2-byte big-endian
// length followed by one raw LZ4 block (not an LZ4 frame) that decompresses
// to at most 32 KiB.
#include <cstddef>
#include <string>
#include <string_view>

namespace auv::detail {

inline constexpr std::size_t kSlocumLz4BlockMax = 32768;

// True when `head` starts with a block whose length fits in `head` (or runs
// past it when head is only the start of the file) and that decompresses to
// text starting with `prefix`. Cheap: decodes only the first block.
bool slocumLz4StartsWith(std::string_view head, std::string_view prefix);

// Every block decompressed and concatenated. Throws InputError naming the
// file and the byte offset of the first bad block.
std::string slocumLz4Decompress(std::string_view data, const std::string& file);

// The same framing, written (test fixtures, the benchmark's compressed input).
std::string slocumLz4Compress(std::string_view data);

}  // namespace auv::detail
