#pragma once
// SHA-256 (FIPS 180-4) for fingerprinting imported mission logs, so the same
// log imported twice is recognised whatever its file name.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace auv {

class Sha256 {
 public:
  Sha256();
  void update(const void* data, std::size_t size);
  void update(std::string_view s) { update(s.data(), s.size()); }
  std::array<std::uint8_t, 32> digest();  // finishes; call once
  std::string hexDigest();                // lower-case, 64 characters

 private:
  void block(const std::uint8_t* p);
  std::array<std::uint32_t, 8> h_;
  std::array<std::uint8_t, 64> buf_{};
  std::size_t buf_len_ = 0;
  std::uint64_t total_bytes_ = 0;
};

std::string sha256Hex(std::string_view data);
// Streams the file; throws InputError naming the file if it cannot be read.
std::string sha256OfFile(const std::string& path);

}  // namespace auv
