#pragma once
// SHA-256 (FIPS 180-4), for the determinism test: the native and the WebAssembly builds print the digest of every
// trace they write, so 4 GB of traces are compared without being written out or piped between programs. The
// digest is the one `sha256sum` prints, so a trace written by `impulse-lab --trace` can be checked against it.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace impulse::web_tests {

class Sha256 {
public:
    void add(std::string_view bytes);
    // The digest as 64 lowercase hex digits. The hasher is spent afterwards.
    std::string hex();

private:
    void block(const unsigned char* p);
    std::array<std::uint32_t, 8> h_{0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                                    0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};  // FIPS 180-4, 5.3.3
    std::array<unsigned char, 64> buffer_{};
    std::size_t buffered_ = 0;
    std::uint64_t length_ = 0;  // bytes added
};

std::string sha256_hex(std::string_view bytes);

}  // namespace impulse::web_tests
