#pragma once
// FNV-1a, 64 bits: the one hash the program writes (a study's identity, results.csv's bytes in its manifest, the tag
// that keeps two cut file names apart). Not a cryptographic hash: it tells apart what differs by accident.
#include <cstdint>
#include <string>
#include <string_view>

#include <fmt/format.h>

namespace vssw::io {

class Fnv1a {
public:
    // Fed piece by piece: the hash of the pieces' concatenation.
    void add(std::string_view bytes) {
        for (const char c : bytes) {
            h_ ^= static_cast<unsigned char>(c);
            h_ *= 1099511628211ull;  // the 64-bit FNV prime
        }
    }
    // 16 lower-case hex digits.
    std::string hex() const { return fmt::format("{:016x}", h_); }

private:
    std::uint64_t h_ = 14695981039346656037ull;  // the 64-bit offset basis
};

// The hash of one text, as 16 hex digits.
inline std::string fnv1a_hex(std::string_view text) {
    Fnv1a h;
    h.add(text);
    return h.hex();
}

}  // namespace vssw::io
