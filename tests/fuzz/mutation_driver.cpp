// A main() for the fuzz harnesses when the compiler has no libFuzzer (GCC): a seeded, deterministic mutation loop
// over a seed corpus. It takes libFuzzer's command line (the subset tests/fuzz/CMakeLists.txt uses), so one CTest
// command serves both builds:
//
//   harness [-seed=N] [-max_total_time=S] [-runs=N] [-max_len=BYTES] [-timeout=S] [-artifact_prefix=DIR/]
//           CORPUS_DIR_OR_FILE...
// (other -flags of libFuzzer are ignored with a note).
//
// Every file of the corpus (directories are read one level deep) is run once as it is, then mutants of them until
// the time or the run count is spent. Given files only (no directory), it runs them once and stops, as libFuzzer
// does: that is how a kept input is replayed. Input k depends only on the seed and the corpus, not on the time, so a
// run is reproducible from its seed (-runs=k stops after input k). Without coverage feedback the mutations are
// chosen for these parsers: number-like tokens replaced by extreme values (nan, inf, -0, 1e308, huge NPTS), line
// edits (empty, duplicated, dropped lines), splices of two corpus files, and byte-level noise.
//
// Before each input runs it is written to <artifact_prefix>current-input: if the harness aborts, crashes, trips a
// sanitizer or hangs until CTest kills it, that file is the input that did it. A clean exit removes it.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

using Input = std::string;
using Rng = std::mt19937_64;

// Mutants are capped at this size unless -max_len says otherwise: the largest seed (the bounds file of the default
// suite) is ~17 kB and the AT2 record ~30 kB; doubling such a file already covers "too many values", and the cap
// keeps chained insertions and splices from growing an input (and the time per run) without bound.
constexpr std::size_t kMaxInputBytes = 128 * 1024;
// Mutations stacked on one input: several at once reach combinations (a bad NPTS and a missing line) that single
// mutations of a valid file cannot; more than a handful mostly produce a first-line syntax error.
constexpr int kMaxStackedMutations = 4;
// A chain keeps mutating its last mutant for up to this many runs before it restarts from a corpus file, so some
// inputs drift far from the seeds while most stay close enough to get past the first checks.
constexpr int kMaxChainLength = 8;
// Defaults when the command line gives none (libFuzzer's own defaults are unbounded; a CTest must not be).
constexpr double kDefaultSeconds = 10.0;
constexpr double kDefaultSlowInputSeconds = 10.0;

// Number-like replacements: the values that break naive parsers (not finite, signed zero, overflow on scaling,
// underflow, subnormal, integer overflow of a count, a huge NPTS, hex and trailing junk that strtod half-accepts).
const std::vector<std::string> kNumberTokens = {
    "nan", "NaN", "-nan", "inf", "-inf", "Infinity", "1e999", "-0", "-0.0", "0", "0.0", "1", "-1", "2",
    "1e308", "-1e308", "1.7976931348623157e308", "4.9e-324", "2.2250738585072014e-308", "1e-320", "1e-300",
    "99999999999999999999", "9223372036854775807", "9223372036854775808", "-9223372036854775809",
    "18446744073709551616", "2147483648", "4294967296", "10000000", "1e7", "1e9", "1e15", "1e300",
    "0x10", "0x1p-1074", "1.0abc", "1e", ".", "-", "+", "", "00000000000000000001", "1_000", "+inf", "0e0"};
// Bytes worth inserting: the separators and delimiters of the two grammars (AT2/two-column and TOML/JSON).
const std::string kInterestingBytes = std::string("\n\r\t ,#=:.-+eE[]{}\"'\\0") + '\0';

bool number_char(char c) {
    return (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E';
}

std::size_t pick(Rng& rng, std::size_t n) {
    return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
}

// Replaces one number-like token (a run of digits, signs, dots and exponents that holds a digit) by an extreme one.
void replace_number(Input& s, Rng& rng) {
    std::vector<std::pair<std::size_t, std::size_t>> tokens;  // [begin, end)
    for (std::size_t i = 0; i < s.size();) {
        if (!number_char(s[i])) { ++i; continue; }
        std::size_t j = i;
        bool digit = false;
        while (j < s.size() && number_char(s[j])) digit |= (s[j] >= '0' && s[j] <= '9'), ++j;
        if (digit) tokens.emplace_back(i, j);
        i = j;
    }
    const std::string& with = kNumberTokens[pick(rng, kNumberTokens.size())];
    if (tokens.empty()) {
        s.insert(pick(rng, s.size() + 1), with);
        return;
    }
    const auto [b, e] = tokens[pick(rng, tokens.size())];
    s.replace(b, e - b, with);
}

// Line boundaries: the begin offset of each line.
std::vector<std::size_t> line_starts(const Input& s) {
    std::vector<std::size_t> starts{0};
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s[i] == '\n' && i + 1 < s.size()) starts.push_back(i + 1);
    return starts;
}

void edit_line(Input& s, Rng& rng) {
    const auto starts = line_starts(s);
    const std::size_t k = pick(rng, starts.size());
    const std::size_t b = starts[k];
    const std::size_t e = k + 1 < starts.size() ? starts[k + 1] : s.size();
    const Input line = s.substr(b, e - b);
    switch (pick(rng, 4)) {
        case 0: s.insert(b, "\n"); break;                      // an empty line
        case 1: s.erase(b, e - b); break;                      // a line dropped
        case 2: s.insert(b, line); break;                      // a line twice
        default: s.insert(b, line.empty() ? "\r\n" : "\r"); break;  // a stray CR (DOS endings, half converted)
    }
}

void splice(Input& s, const std::vector<Input>& corpus, Rng& rng) {
    const Input& other = corpus[pick(rng, corpus.size())];
    const std::size_t cut = pick(rng, s.size() + 1);
    const std::size_t from = pick(rng, other.size() + 1);
    s = s.substr(0, cut) + other.substr(from);
}

void mutate_once(Input& s, const std::vector<Input>& corpus, Rng& rng) {
    switch (pick(rng, 9)) {
        case 0:
            if (!s.empty()) s[pick(rng, s.size())] ^= static_cast<char>(1u << pick(rng, 8));  // bit flip
            break;
        case 1: s.insert(pick(rng, s.size() + 1), 1, kInterestingBytes[pick(rng, kInterestingBytes.size())]); break;
        case 2: s.insert(pick(rng, s.size() + 1), 1, static_cast<char>(pick(rng, 256))); break;
        case 3:
            if (!s.empty()) s.erase(pick(rng, s.size()), 1 + pick(rng, 8));  // a few bytes deleted
            break;
        case 4: s.resize(pick(rng, s.size() + 1)); break;  // truncated
        case 5: splice(s, corpus, rng); break;
        case 6: edit_line(s, rng); break;
        default: replace_number(s, rng); break;  // 2 of 9: the mutation these parsers care most about
    }
}

struct Options {
    std::uint64_t seed = 1;
    double seconds = kDefaultSeconds;
    double slow_input_seconds = kDefaultSlowInputSeconds;
    long long runs = -1;  // -1: bounded by time only
    std::size_t max_len = kMaxInputBytes;
    std::string artifact_prefix = "./";
    std::vector<std::string> paths;
};

bool flag(const std::string& arg, const char* name, std::string& value) {
    const std::string prefix = std::string("-") + name + "=";
    if (arg.compare(0, prefix.size(), prefix) != 0) return false;
    value = arg.substr(prefix.size());
    return true;
}

Options parse_options(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        std::string v;
        if (flag(arg, "seed", v)) o.seed = std::stoull(v);
        else if (flag(arg, "max_total_time", v)) o.seconds = std::stod(v);
        else if (flag(arg, "runs", v)) o.runs = std::stoll(v);
        else if (flag(arg, "max_len", v)) o.max_len = std::stoull(v);
        else if (flag(arg, "timeout", v)) o.slow_input_seconds = std::stod(v);
        else if (flag(arg, "artifact_prefix", v)) o.artifact_prefix = v;
        else if (!arg.empty() && arg[0] == '-')
            std::fprintf(stderr, "mutation_driver: ignoring libFuzzer flag %s\n", arg.c_str());
        else o.paths.push_back(arg);
    }
    return o;
}

std::vector<Input> read_corpus(const std::vector<std::string>& paths) {
    namespace fs = std::filesystem;
    std::vector<std::string> files;
    for (const auto& p : paths) {
        if (fs::is_directory(p)) {
            for (const auto& entry : fs::directory_iterator(p))
                if (entry.is_regular_file()) files.push_back(entry.path().string());
        } else {
            files.push_back(p);
        }
    }
    std::sort(files.begin(), files.end());  // directory order is not deterministic
    std::vector<Input> corpus;
    for (const auto& f : files) {
        std::ifstream in(f, std::ios::binary);
        if (!in) {
            std::fprintf(stderr, "mutation_driver: cannot read %s\n", f.c_str());
            std::exit(2);
        }
        corpus.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    return corpus;
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parse_options(argc, argv);
    const std::vector<Input> corpus = read_corpus(o.paths);
    if (corpus.empty()) {
        std::fprintf(stderr, "mutation_driver: no corpus (give files or directories)\n");
        return 2;
    }
    namespace fs = std::filesystem;
    const bool replay_only =
        std::none_of(o.paths.begin(), o.paths.end(), [](const std::string& p) { return fs::is_directory(p); });
    const std::string current = o.artifact_prefix + "current-input";
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const auto seconds_since = [](Clock::time_point t) {
        return std::chrono::duration<double>(Clock::now() - t).count();
    };

    Rng rng(o.seed);
    Input input;
    int chain = 0;
    long long run = 0;
    for (;; ++run) {
        if (o.runs >= 0 && run >= o.runs) break;
        if (replay_only && run >= static_cast<long long>(corpus.size())) break;
        // The time bound is checked only after the corpus has run once unchanged.
        if (run >= static_cast<long long>(corpus.size()) && seconds_since(start) >= o.seconds) break;
        if (run < static_cast<long long>(corpus.size())) {
            input = corpus[static_cast<std::size_t>(run)];
        } else {
            if (chain == 0 || chain >= kMaxChainLength) {
                input = corpus[pick(rng, corpus.size())];
                chain = 0;
            }
            ++chain;
            const std::size_t n = 1 + pick(rng, kMaxStackedMutations);
            for (std::size_t m = 0; m < n; ++m) mutate_once(input, corpus, rng);
            if (input.size() > o.max_len) input.resize(o.max_len);
        }
        {
            std::ofstream out(current, std::ios::binary | std::ios::trunc);
            out.write(input.data(), static_cast<std::streamsize>(input.size()));
        }
        const auto t0 = Clock::now();
        LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
        const double took = seconds_since(t0);
        if (took > o.slow_input_seconds) {
            std::fprintf(stderr,
                         "mutation_driver: FINDING: run %lld took %.1f s (> -timeout=%g s); input kept in %s "
                         "(replay: -seed=%llu -runs=%lld)\n",
                         run, took, o.slow_input_seconds, current.c_str(),
                         static_cast<unsigned long long>(o.seed), run + 1);
            return 1;
        }
    }
    std::remove(current.c_str());
    std::printf("mutation_driver: %lld runs in %.1f s (seed %llu, %zu corpus files), no finding\n", run,
                seconds_since(start), static_cast<unsigned long long>(o.seed), corpus.size());
    return 0;
}
