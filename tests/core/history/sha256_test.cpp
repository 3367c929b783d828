#include "history/sha256.h"

#include <gtest/gtest.h>

#include "common/input_error.h"
#include "temp_dir.h"

namespace auv {

// FIPS 180-2 Appendix B.1: one-block message "abc".
TEST(Sha256, Fips180OneBlockAbc) {
  EXPECT_EQ(sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

// FIPS 180-2 Appendix B.2: the 448-bit two-block message.
TEST(Sha256, Fips180TwoBlock448Bit) {
  const std::string m = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
  ASSERT_EQ(m.size() * 8, 448u);
  EXPECT_EQ(sha256Hex(m), "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

// FIPS 180-2 Appendix B.3: one million 'a', fed in uneven chunks so that the
// block buffering across update() calls is exercised.
TEST(Sha256, Fips180MillionAInChunks) {
  Sha256 h;
  const std::string chunk(997, 'a');
  std::size_t left = 1000000;
  while (left > 0) {
    const std::size_t n = std::min(left, chunk.size());
    h.update(chunk.data(), n);
    left -= n;
  }
  EXPECT_EQ(h.hexDigest(), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

// The empty message (FIPS 180-4 examples; also `sha256sum /dev/null`).
TEST(Sha256, EmptyMessage) {
  EXPECT_EQ(sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

// Padding edge: 55 bytes fit one block with the length, 56 need a second.
TEST(Sha256, FileHashEqualsStringHashAcrossPaddingBoundary) {
  test::TempDir dir;
  for (std::size_t n : {55u, 56u, 63u, 64u, 65u, 70000u}) {
    std::string data;
    for (std::size_t i = 0; i < n; ++i) data += char('A' + i % 26);
    test::writeAll(dir.file("m.log"), data);
    EXPECT_EQ(sha256OfFile(dir.file("m.log")), sha256Hex(data)) << n;
  }
  EXPECT_THROW(sha256OfFile(dir.file("missing.log")), InputError);
}

}  // namespace auv
