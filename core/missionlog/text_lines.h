#pragma once
// Line-by-line reading of large text files in blocks, shared by the text
// readers: bounded memory (one block), lines handed out as views into the
// block, lines longer than a block skipped and flagged, progress and
// cancellation once per block. The same loop runs on text already in memory
// (tests, fuzzers).
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "missionlog/read_options.h"

namespace auv {

enum class LineFlag {
  kNormal,
  kFinalNoNewline,  // the last line of the file has no line end
  kOverlong,        // the line was longer than the block; `text` is empty
};

// A file opened for block reads; throws InputError (naming the file) when it
// cannot be opened, is a directory, or a read fails.
class BlockFile {
 public:
  explicit BlockFile(const std::filesystem::path& path);
  ~BlockFile();
  BlockFile(const BlockFile&) = delete;
  BlockFile& operator=(const BlockFile&) = delete;
  std::uint64_t size() const { return size_; }
  const std::string& name() const { return name_; }
  std::size_t read(char* dst, std::size_t n);  // 0 at the end

 private:
  std::string name_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

// Calls onLine(std::string_view line, LineFlag flag) for every line (without
// '\n'; a trailing '\r' is removed). `pull(dst, n)` fills a buffer and returns
// the bytes read (0 at the end). onLine returns false to stop early.
template <class Pull, class OnLine>
void forEachLine(const std::string& name, std::uint64_t total, Pull&& pull, const ReadOptions& options,
                 OnLine&& onLine) {
  const std::size_t cap = std::max<std::size_t>(options.block_bytes, 64);
  std::unique_ptr<char[]> buf(new char[cap]);
  std::size_t carry = 0;
  std::uint64_t consumed = 0;
  bool skipping = false;
  auto emit = [&](const char* b, const char* e, LineFlag f) {
    if (e > b && e[-1] == '\r') --e;
    return onLine(std::string_view(b, static_cast<std::size_t>(e - b)), f);
  };
  if (options.progress && !options.progress(0.0)) throw ReadCancelled(name);
  for (;;) {
    const std::size_t got = pull(buf.get() + carry, cap - carry);
    if (got == 0) {
      if (skipping) onLine(std::string_view(), LineFlag::kOverlong);
      else if (carry > 0) emit(buf.get(), buf.get() + carry, LineFlag::kFinalNoNewline);
      break;
    }
    consumed += got;
    const std::size_t avail = carry + got;
    char* b = buf.get();
    const char* e = b + avail;
    const char* p = b;
    if (skipping) {
      const auto* nl = static_cast<const char*>(std::memchr(p, '\n', avail));
      if (!nl) {
        carry = 0;
      } else {
        skipping = false;
        if (!onLine(std::string_view(), LineFlag::kOverlong)) return;
        p = nl + 1;
      }
    }
    if (!skipping) {
      for (;;) {
        const auto* nl = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(e - p)));
        if (!nl) break;
        if (!emit(p, nl, LineFlag::kNormal)) return;
        p = nl + 1;
      }
      carry = static_cast<std::size_t>(e - p);
      if (carry == cap) {  // no line end in a full buffer
        skipping = true;
        carry = 0;
      } else if (carry) {
        std::memmove(b, p, carry);
      }
    }
    if (options.progress && total > 0 &&
        !options.progress(std::min(1.0, static_cast<double>(consumed) / static_cast<double>(total))))
      throw ReadCancelled(name);
  }
  if (options.progress && !options.progress(1.0)) throw ReadCancelled(name);
}

// Pull functions for forEachLine.
struct MemoryPull {
  std::string_view text;
  std::size_t pos = 0;
  std::size_t operator()(char* dst, std::size_t n) {
    const std::size_t k = std::min(n, text.size() - pos);
    if (k) std::memcpy(dst, text.data() + pos, k);
    pos += k;
    return k;
  }
};

struct FilePull {
  BlockFile* file;
  std::size_t operator()(char* dst, std::size_t n) { return file->read(dst, n); }
};

}  // namespace auv
