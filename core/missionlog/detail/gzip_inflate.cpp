#include "missionlog/detail/gzip_inflate.h"

#include <zlib.h>

#include <algorithm>
#include <limits>

#include "common/input_error.h"
#include "missionlog/read_options.h"

namespace auv::detail {
namespace {

// zlib counts in uInt; feed it in slices well below that.
constexpr std::size_t kSlice = std::size_t{1} << 20;

struct Inflater {
  z_stream z{};
  bool open = false;
  Inflater() {
    // 16 + MAX_WBITS: gzip wrapper only (a zlib or raw stream is not a .gz file).
    open = inflateInit2(&z, 16 + MAX_WBITS) == Z_OK;
  }
  ~Inflater() {
    if (open) inflateEnd(&z);
  }
};

}  // namespace

bool isGzip(std::string_view b) {
  return b.size() >= 3 && static_cast<unsigned char>(b[0]) == 0x1f && static_cast<unsigned char>(b[1]) == 0x8b &&
         b[2] == 8;
}

InflateResult inflateGzip(std::string_view gz, const std::string& file, std::size_t maxBytes,
                          const std::function<bool(double)>& progress) {
  if (!isGzip(gz))
    throw InputError("gzip", "not a gzip file (no 1f 8b 08 magic bytes at the start)",
                     "decompress the file or give the original .gz the vehicle wrote", {file, 0, 0});
  InflateResult out;
  Inflater inf;
  if (!inf.open) throw InputError("gzip", "zlib could not start", "try again (out of memory?)", {file, 0, 0});
  std::size_t in = 0;
  char buf[1 << 16];
  while (true) {
    if (inf.z.avail_in == 0 && in < gz.size()) {
      const std::size_t n = std::min(kSlice, gz.size() - in);
      inf.z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(gz.data() + in));
      inf.z.avail_in = static_cast<uInt>(n);
      in += n;
      if (progress && !progress(static_cast<double>(in) / static_cast<double>(gz.size()) * 0.5))
        throw ReadCancelled(file);
    }
    inf.z.next_out = reinterpret_cast<Bytef*>(buf);
    inf.z.avail_out = sizeof buf;
    const int st = inflate(&inf.z, Z_NO_FLUSH);
    const std::size_t got = sizeof buf - inf.z.avail_out;
    if (out.text.size() + got > maxBytes)
      throw InputError("gzip",
                       "decompresses to more than " + std::to_string(maxBytes >> 20) +
                           " MiB (a damaged length or a hostile file), stopped at compressed byte " +
                           std::to_string(in - inf.z.avail_in),
                       "check the file; split a genuine log this large into smaller files", {file, 0, 0});
    out.text.append(buf, got);
    const std::uint64_t at = in - inf.z.avail_in;
    if (st == Z_STREAM_END) {
      // Concatenated members (gzip -c a b > ab.gz) are one file; trailing
      // zero padding (some loggers pad to a block) ends it quietly.
      const std::string_view rest = gz.substr(static_cast<std::size_t>(at));
      if (rest.empty() || rest.find_first_not_of('\0') == std::string_view::npos) break;
      if (!isGzip(rest)) {
        out.complete = false;
        out.stopped_at = at;
        out.damage = "bytes after the end of the gzip data";
        break;
      }
      inflateReset(&inf.z);
      continue;
    }
    if (st == Z_OK) continue;
    if (st == Z_BUF_ERROR && inf.z.avail_in == 0) {
      if (in < gz.size()) continue;  // the next slice of input
      out.complete = false;
      out.stopped_at = at;
      out.damage = "the compressed data ends early (file cut short)";
      break;
    }
    out.complete = false;
    out.stopped_at = at;
    out.damage = std::string("damaged compressed data (") + (inf.z.msg ? inf.z.msg : "zlib error") + ")";
    break;
  }
  if (out.text.empty() && !out.complete)
    throw InputError("gzip", out.damage + " at compressed byte " + std::to_string(out.stopped_at) + "; nothing could be read",
                     "copy the file again from the glider or its data server", {file, 0, 0});
  return out;
}

std::string inflateGzipHead(std::string_view gz, std::size_t maxBytes) {
  std::string out;
  if (!isGzip(gz)) return out;
  Inflater inf;
  if (!inf.open) return out;
  inf.z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(gz.data()));
  inf.z.avail_in = static_cast<uInt>(std::min<std::size_t>(gz.size(), std::numeric_limits<uInt>::max()));
  out.resize(maxBytes);
  inf.z.next_out = reinterpret_cast<Bytef*>(out.data());
  inf.z.avail_out = static_cast<uInt>(maxBytes);
  inflate(&inf.z, Z_SYNC_FLUSH);
  out.resize(maxBytes - inf.z.avail_out);
  return out;
}

}  // namespace auv::detail
