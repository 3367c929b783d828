#pragma once
// gzip (RFC 1952) through zlib, for loggers that compress their files
// (SeaExplorer *.gli.sub.N.gz / *.pld1.raw.N.gz). A file cut short or damaged
// part-way keeps what decompressed cleanly before the damage, and says where
// it stopped, so the reader can keep those rows and report the rest; a file
// that decompresses to more than a limit (a damaged length or a "zip bomb")
// is refused.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace auv::detail {

// True when `bytes` start with the gzip magic (1f 8b 08).
bool isGzip(std::string_view bytes);

struct InflateResult {
  std::string text;             // what decompressed before the end or the damage
  bool complete = true;         // false: the stream ends early or is damaged
  std::uint64_t stopped_at = 0; // compressed byte offset where it stopped (when !complete)
  std::string damage;           // zlib's words for the damage ("" when complete)
};

// Decompresses every gzip member of `gz`. Throws InputError naming `file`
// when the data is not gzip at all, when nothing could be decompressed, or
// when the output would exceed `maxBytes`. `progress` (optional) gets the
// fraction of the input consumed and may return false to stop (the caller
// then throws ReadCancelled).
InflateResult inflateGzip(std::string_view gz, const std::string& file, std::size_t maxBytes,
                          const std::function<bool(double)>& progress = {});

// Decompresses at most `maxBytes` from the start of `gz`, ignoring damage and
// the end of the input: for content sniffing on the first bytes of a file.
std::string inflateGzipHead(std::string_view gz, std::size_t maxBytes);

}  // namespace auv::detail
