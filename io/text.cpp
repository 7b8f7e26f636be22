#include "io/text.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>

#include <fmt/format.h>

#include "io/fnv1a.hpp"

namespace vssw::io {

std::string num(double value) { return fmt::format("{:.6g}", value); }

std::string yes_no(bool value) { return value ? "yes" : "no"; }

std::string percent(double rel_error) {
    if (!std::isfinite(rel_error)) return "n/a";
    const double p = 100.0 * rel_error;
    const double a = std::abs(p);
    if (a == 0.0) return "0 %";
    if (a >= 1.0) return fmt::format("{:+.1f} %", p);
    if (a >= 0.01) return fmt::format("{:+.2f} %", p);
    return fmt::format("{:+.1e} %", p);
}

std::string one_line(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    return text;
}

std::string file_stem(const std::string& case_id) {
    std::string s = case_id;
    for (char& c : s) {
        if (c == '/') c = '_';
        else if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_')) c = '-';
    }
    if (s.size() <= kMaxFileStem) return s;
    // Too long for a file name once a prefix and an extension are added: cut, and told apart from every other cut
    // name by a hash of the whole name (FNV-1a, 64 bits), so that two long names never share a file.
    const std::string tag = "-" + fnv1a_hex(case_id);
    return s.substr(0, kMaxFileStem - tag.size()) + tag;
}

namespace {

// The length of the well-formed UTF-8 character at text[i] (1 to 4), or 0 when the bytes there are not one: a stray
// continuation byte, a truncated sequence, an overlong form, a surrogate or a code point above U+10FFFF. The code
// point is stored in *code.
std::size_t utf8_char(std::string_view text, std::size_t i, std::uint32_t* code) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char c = byte(i);
    const std::size_t n = c < 0x80 ? 1 : (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : (c & 0xF8) == 0xF0 ? 4 : 0;
    if (n == 0 || i + n > text.size()) return 0;
    std::uint32_t cp = n == 1 ? c : c & (0x7Fu >> n);
    for (std::size_t k = 1; k < n; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return 0;
        cp = (cp << 6) | (byte(i + k) & 0x3Fu);
    }
    constexpr std::uint32_t kLeast[] = {0, 0, 0x80, 0x800, 0x10000};  // below these, a shorter form exists (overlong)
    if (cp < kLeast[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
    *code = cp;
    return n;
}

}  // namespace

std::optional<std::string> not_utf8(std::string_view text) {
    std::uint32_t code = 0;
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t n = utf8_char(text, i, &code);
        if (n == 0)
            return fmt::format("'{}' is not UTF-8 (the byte \\x{:02x} at offset {})", printable(text),
                               static_cast<unsigned char>(text[i]), i);
        i += n;
    }
    return std::nullopt;
}

namespace {

// The Unicode marks that reorder how the rest of a line is shown (embeddings, overrides, isolates, the implicit
// marks): a name holding U+202E would show a message's words in another order than they are (Trojan Source).
bool is_direction_mark(std::uint32_t code) {
    return code == 0x061C || code == 0x200E || code == 0x200F || (code >= 0x202A && code <= 0x202E) ||
           (code >= 0x2066 && code <= 0x2069);
}

}  // namespace

std::string printable(std::string_view text) {
    std::string s;
    std::uint32_t code = 0;
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t n = utf8_char(text, i, &code);
        if (n == 0) {
            s += fmt::format("\\x{:02x}", static_cast<unsigned char>(text[i]));
            ++i;
            continue;
        }
        if (code == '\n') s += "\\n";
        else if (code == '\r') s += "\\r";
        else if (code == '\t') s += "\\t";
        else if (code < 0x20 || code == 0x7F) s += fmt::format("\\x{:02x}", code);
        else if ((code >= 0x80 && code <= 0x9F) || is_direction_mark(code)) s += fmt::format("\\u{:04x}", code);
        else s.append(text.substr(i, n));
        i += n;
    }
    return s;
}

}  // namespace vssw::io
