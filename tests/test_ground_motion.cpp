// Ground motions: the shipped records, both PEER AT2 header styles, two-column files, every input error, linear
// interpolation, scaling and the synthetic pulses.
#include "analytic/ground_motion.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "analytic/error.hpp"

namespace vssw {
namespace {

constexpr double kG0 = 9.80665;  // standard gravity, m/s^2
constexpr double kPi = 3.141592653589793;
// SOURCES.md rounds PGA to 3 decimals (0.825195 g -> 0.825, 0.31882 g -> 0.319): half a unit in the last place.
constexpr double kRoundedPgaTol_g = 5e-4;
// Relative rounding of a few double operations (unit conversion, i * dt, interpolation weights).
constexpr double kRoundoff = 1e-12;
// Two forms of one linear interpolation ((1 - w) a_i + w a_i+1 in GroundMotion; a_i + slope (x - t_i) in a piece, or
// a_i + (x - t_i) / dt_i (a_i+1 - a_i) in the test's) each round twice (weight or slope, then the sum): 4 roundoffs.
constexpr double kInterpolationsApart = 4.0 * kRoundoff;
// An analytic signal's PGA is the peak its maker states (AnalyticShape), compared here with the amplitude written in
// the test: only the rounding of a few operations remains.
constexpr double kStatedPeakTol = 1e-9;

const std::string kDataDir = VSSW_DATA_DIR;

// Writes `content` to a fresh file in the test temp dir and returns its path.
std::string temp_file(const std::string& name, const std::string& content) {
    const std::string path = testing::TempDir() + "vssw_gm_" + name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << content;
    return path;
}

// A small AT2 file: the two free text lines, then units line 3, counts line 4 and the value lines.
std::string at2_text(const std::string& line3, const std::string& line4, const std::string& values) {
    return "PEER NGA STRONG MOTION DATABASE RECORD\nTEST EVENT, TEST STATION, 000\n" + line3 + "\n" + line4 + "\n" +
           values;
}

const std::string kUnitsG = "ACCELERATION TIME HISTORY IN UNITS OF G";
const std::string kOlderLine4 = "6    0.0200    NPTS, DT";
const std::string kWest2Line4 = "NPTS=     6, DT=   .0200 SEC";
const std::string kSixValues =  // 6 values, 5 per line, Fortran E format
    "   0.100000E-01  -0.200000E-01   0.300000E-01   0.400000E-01  -0.500000E-01\n"
    "   0.600000E-01\n";
const std::vector<double> kSixValuesG{0.01, -0.02, 0.03, 0.04, -0.05, 0.06};

// Runs f, which must throw InputError whose message contains every fragment.
void expect_input_error(const std::function<void()>& f, std::initializer_list<std::string> fragments) {
    try {
        f();
        ADD_FAILURE() << "expected InputError, nothing was thrown";
    } catch (const InputError& e) {
        const std::string what = e.what();
        for (const std::string& fragment : fragments)
            EXPECT_NE(what.find(fragment), std::string::npos) << "message '" << what << "' lacks '" << fragment << "'";
    }
}

void expect_at2_error(const std::string& name, const std::string& content,
                      std::initializer_list<std::string> fragments) {
    const std::string path = temp_file(name, content);
    expect_input_error([&] { read_peer_at2(path); }, fragments);
}

void expect_two_column_error(const std::string& name, const std::string& content,
                             std::initializer_list<std::string> fragments) {
    const std::string path = temp_file(name, content);
    expect_input_error([&] { read_two_column(path, AccelUnits::g); }, fragments);
}

// Reference for interpolation: a linear scan for the bracketing samples, independent of the class's lookup.
double reference_interpolation(const std::vector<double>& t, const std::vector<double>& a, double x) {
    if (x < t.front() || x > t.back()) return 0.0;
    for (std::size_t i = 0; i + 1 < t.size(); ++i)
        if (x <= t[i + 1]) return a[i] + (x - t[i]) / (t[i + 1] - t[i]) * (a[i + 1] - a[i]);
    return a.back();
}

// --- shipped records ----------------------------------------------------------------------------------------------

TEST(GroundMotion, ReadsShippedRinaldiRecord) {
    const GroundMotion m = read_peer_at2(kDataDir + "/NGA_no_1063_RRS228.AT2");
    ASSERT_EQ(m.sample_values().size(), 1991u);
    EXPECT_EQ(m.sample_times().front(), 0.0);
    EXPECT_NEAR(m.sample_times()[1] - m.sample_times()[0], 0.01, kRoundoff);
    EXPECT_NEAR(m.duration(), 19.90, kRoundoff * 19.90);
    EXPECT_NEAR(m.pga() / kG0, 0.825, kRoundedPgaTol_g);
    EXPECT_NEAR(m.sample_values().front(), -0.731461E-02 * kG0, kRoundoff);
    EXPECT_NEAR(m(0.0), -0.731461E-02 * kG0, kRoundoff);  // records may start at a non-zero value
    EXPECT_EQ(m.name(), "NGA_no_1063_RRS228.AT2");
    EXPECT_FALSE(m.is_zero());
}

TEST(GroundMotion, ReadsShippedElCentroRecord) {
    const GroundMotion m = read_two_column(kDataDir + "/elcentro_chopra.txt", AccelUnits::g);
    ASSERT_EQ(m.sample_values().size(), 1561u);
    EXPECT_NEAR(m.sample_times()[1] - m.sample_times()[0], 0.02, kRoundoff);
    EXPECT_NEAR(m.duration(), 31.20, kRoundoff * 31.20);
    EXPECT_NEAR(m.pga() / kG0, 0.319, kRoundedPgaTol_g);
    EXPECT_NEAR(m.sample_values()[1], 0.0063 * kG0, kRoundoff);
}

TEST(GroundMotion, ReadRecordChoosesReaderByContent) {
    const GroundMotion at2 = read_record(kDataDir + "/NGA_no_1063_RRS228.AT2");
    const GroundMotion two = read_record(kDataDir + "/elcentro_chopra.txt");
    EXPECT_EQ(at2.sample_values(), read_peer_at2(kDataDir + "/NGA_no_1063_RRS228.AT2").sample_values());
    EXPECT_EQ(two.sample_values(), read_two_column(kDataDir + "/elcentro_chopra.txt", AccelUnits::g).sample_values());
    // Explicit units apply to the two-column file (and override the AT2 header).
    const AccelUnits cm = AccelUnits::cm_per_s2;
    EXPECT_NEAR(read_record(kDataDir + "/elcentro_chopra.txt", &cm).sample_values()[1], 0.0063 * 0.01, kRoundoff);
    EXPECT_NEAR(read_record(kDataDir + "/NGA_no_1063_RRS228.AT2", &cm).sample_values()[0], -0.731461E-02 * 0.01,
                kRoundoff);
}

// parse_record is read_record on text (the fuzz harness's entry, tests/fuzz/): same samples, the name in messages.
TEST(GroundMotion, ParseRecordReadsTextAsReadRecordReadsFiles) {
    for (const std::string file : {"NGA_no_1063_RRS228.AT2", "elcentro_chopra.txt"}) {
        std::ifstream in(kDataDir + "/" + file, std::ios::binary);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const GroundMotion from_text = parse_record(text, file);
        const GroundMotion from_file = read_record(kDataDir + "/" + file);
        EXPECT_EQ(from_text.sample_times(), from_file.sample_times()) << file;
        EXPECT_EQ(from_text.sample_values(), from_file.sample_values()) << file;
        EXPECT_EQ(from_text.name(), file);
    }
    expect_input_error([] { parse_record("", "empty-text"); }, {"empty-text", "empty"});
    expect_input_error([] { parse_record(at2_text(kUnitsG, kOlderLine4, "0.1 0.2\n"), "short.at2"); },
                       {"short.at2", "NPTS = 6"});
}

// --- PEER AT2 headers ---------------------------------------------------------------------------------------------

TEST(GroundMotion, ReadsOlderAt2Header) {
    const GroundMotion m = read_peer_at2(temp_file("older.at2", at2_text(kUnitsG, kOlderLine4, kSixValues)));
    ASSERT_EQ(m.sample_values().size(), kSixValuesG.size());
    for (std::size_t i = 0; i < kSixValuesG.size(); ++i) {
        EXPECT_NEAR(m.sample_values()[i], kSixValuesG[i] * kG0, kRoundoff) << i;
        EXPECT_NEAR(m.sample_times()[i], 0.02 * static_cast<double>(i), kRoundoff) << i;
    }
}

TEST(GroundMotion, NgaWest2HeaderGivesSameSamplesAsOlderStyle) {
    const GroundMotion older = read_peer_at2(temp_file("same_old.at2", at2_text(kUnitsG, kOlderLine4, kSixValues)));
    const GroundMotion west2 = read_peer_at2(temp_file("same_new.at2", at2_text(kUnitsG, kWest2Line4, kSixValues)));
    EXPECT_EQ(older.sample_times(), west2.sample_times());
    EXPECT_EQ(older.sample_values(), west2.sample_values());
}

TEST(GroundMotion, At2HeaderToleratesSpacingCommasAndCase) {
    const GroundMotion reference = read_peer_at2(temp_file("ref.at2", at2_text(kUnitsG, kOlderLine4, kSixValues)));
    const std::vector<std::string> line4s{
        "NPTS=6,DT=.02SEC",         "npts=  6, dt=  0.0200 sec", "NPTS = 6 , DT = 0.02 SEC,",
        "6, 0.02, NPTS, DT",        "   6 .02 npts dt",           "\t6\t0.0200\tNPTS, DT\t",
        "NPTS=     6  DT=   .0200", "6  2.0E-02  NPTS, DT"};
    for (std::size_t k = 0; k < line4s.size(); ++k) {
        SCOPED_TRACE(line4s[k]);
        const GroundMotion m =
            read_peer_at2(temp_file("variant" + std::to_string(k) + ".at2", at2_text(kUnitsG, line4s[k], kSixValues)));
        EXPECT_EQ(m.sample_times(), reference.sample_times());
        EXPECT_EQ(m.sample_values(), reference.sample_values());
    }
}

TEST(GroundMotion, At2AcceptsDosLineEndingsAndLowercaseUnits) {
    std::string text = at2_text("acceleration time series in units of g", kWest2Line4, kSixValues);
    std::string crlf;
    for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    const GroundMotion m = read_peer_at2(temp_file("crlf.at2", crlf));
    ASSERT_EQ(m.sample_values().size(), kSixValuesG.size());
    EXPECT_NEAR(m.sample_values()[5], 0.06 * kG0, kRoundoff);
}

TEST(GroundMotion, At2ReadsCentimetreAndMetreUnits) {
    struct Case {
        std::string line3;
        double factor;
    };
    const std::vector<Case> cases{{"ACCELERATION TIME HISTORY IN CM/S/S", 0.01},
                                  {"ACCELERATION IN UNITS OF CM/S^2", 0.01},
                                  {"ACCELERATION (CM/SEC/SEC)", 0.01},
                                  {"ACCELERATION TIME HISTORY IN GAL", 0.01},
                                  {"ACCELERATION IN M/S/S", 1.0},
                                  {"ACCELERATION IN M/S^2", 1.0}};
    for (std::size_t k = 0; k < cases.size(); ++k) {
        SCOPED_TRACE(cases[k].line3);
        const GroundMotion m = read_peer_at2(
            temp_file("units" + std::to_string(k) + ".at2", at2_text(cases[k].line3, kOlderLine4, kSixValues)));
        EXPECT_NEAR(m.sample_values()[2], 0.03 * cases[k].factor, kRoundoff);
    }
}

TEST(GroundMotion, At2UnitsOverrideReplacesHeader) {
    const std::string path = temp_file("override.at2", at2_text(kUnitsG, kOlderLine4, kSixValues));
    const AccelUnits cm = AccelUnits::cm_per_s2;
    EXPECT_NEAR(read_peer_at2(path, &cm).sample_values()[2], 0.03 * 0.01, kRoundoff);
}

TEST(GroundMotion, At2WithoutReadableUnitsNeedsOverride) {
    const std::string path = temp_file("nounits.at2", at2_text("ACCELERATION TIME HISTORY", kOlderLine4, kSixValues));
    expect_input_error([&] { read_peer_at2(path); }, {path, ":3:", "ACCELERATION TIME HISTORY", "units"});
    const AccelUnits g = AccelUnits::g;
    EXPECT_NEAR(read_peer_at2(path, &g).sample_values()[2], 0.03 * kG0, kRoundoff);
}

TEST(GroundMotion, At2RejectsVelocityHistory) {
    expect_at2_error("velocity.vt2", at2_text("VELOCITY TIME HISTORY IN UNITS OF CM/S", kOlderLine4, kSixValues),
                     {":3:", "not an acceleration"});
}

// --- PEER AT2 errors ----------------------------------------------------------------------------------------------

TEST(GroundMotion, MissingFileIsInputError) {
    const std::string path = testing::TempDir() + "vssw_gm_does_not_exist.at2";
    expect_input_error([&] { read_peer_at2(path); }, {path, "cannot open"});
    expect_input_error([&] { read_two_column(path, AccelUnits::g); }, {path, "cannot open"});
    expect_input_error([&] { read_record(path); }, {path, "cannot open"});
    expect_input_error([&] { read_record(testing::TempDir()); }, {"directory"});
}

// What is not a regular file is refused before it is opened: /dev/zero used to be read until memory ran out, a FIFO
// blocked forever. A file past kMaxRecordBytes is refused by its size (a sparse file: nothing is written).
TEST(GroundMotion, DevicesFifosAndHugeFilesAreRefusedUnread) {
    expect_input_error([] { read_record("/dev/zero"); }, {"/dev/zero", "not a regular file"});
    const std::string fifo = testing::TempDir() + "vssw_gm_fifo";
    std::remove(fifo.c_str());
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    expect_input_error([&] { read_record(fifo); }, {fifo, "not a regular file"});  // returns: nothing opened it
    std::remove(fifo.c_str());
    const std::string huge = temp_file("huge.txt", "");
    std::filesystem::resize_file(huge, static_cast<std::uintmax_t>(kMaxRecordBytes) + 1);
    expect_input_error([&] { read_record(huge); }, {huge, "67108865 bytes", "67108864"});
    std::remove(huge.c_str());
}

TEST(GroundMotion, EmptyFileIsInputError) {
    expect_at2_error("empty.at2", "", {"empty.at2", "empty"});
    expect_two_column_error("empty.txt", "", {"empty.txt", "empty"});
}

TEST(GroundMotion, TruncatedAt2HeaderIsInputError) {
    expect_at2_error("trunc_header.at2", "PEER NGA STRONG MOTION DATABASE RECORD\nTEST\n" + kUnitsG + "\n",
                     {"trunc_header.at2", "truncated header", "3 line"});
}

TEST(GroundMotion, At2HeaderWithoutNptsOrDtIsInputError) {
    expect_at2_error("no_npts.at2", at2_text(kUnitsG, "6    0.0200", kSixValues), {":4:", "no NPTS"});
    expect_at2_error("no_dt.at2", at2_text(kUnitsG, "NPTS=  6", kSixValues), {":4:", "no DT"});
    expect_at2_error("no_dt_value.at2", at2_text(kUnitsG, "NPTS=  6, DT=", kSixValues), {":4:", "NPTS and DT"});
    expect_at2_error("one_number.at2", at2_text(kUnitsG, "6    NPTS, DT", kSixValues), {":4:", "NPTS and DT"});
    expect_at2_error("bad_npts.at2", at2_text(kUnitsG, "NPTS= six, DT= .02", kSixValues), {":4:", "'SIX'"});
    expect_at2_error("bad_dt.at2", at2_text(kUnitsG, "6  0.02x  NPTS, DT", kSixValues), {":4:", "'0.02X'"});
}

TEST(GroundMotion, At2NptsAndDtMustBePositiveAndFinite) {
    expect_at2_error("npts0.at2", at2_text(kUnitsG, "0  0.02  NPTS, DT", kSixValues), {":4:", "NPTS", "0"});
    expect_at2_error("npts_neg.at2", at2_text(kUnitsG, "NPTS= -6, DT= .02", kSixValues), {":4:", "NPTS", "-6"});
    expect_at2_error("npts_frac.at2", at2_text(kUnitsG, "6.5  0.02  NPTS, DT", kSixValues), {":4:", "NPTS", "6.5"});
    expect_at2_error("npts_inf.at2", at2_text(kUnitsG, "inf  0.02  NPTS, DT", kSixValues), {":4:", "NPTS", "inf"});
    expect_at2_error("dt0.at2", at2_text(kUnitsG, "6  0.0  NPTS, DT", kSixValues), {":4:", "DT", "0.0"});
    expect_at2_error("dt_neg.at2", at2_text(kUnitsG, "NPTS= 6, DT= -.02 SEC", kSixValues), {":4:", "DT", "-.02"});
    expect_at2_error("dt_nan.at2", at2_text(kUnitsG, "6  nan  NPTS, DT", kSixValues), {":4:", "DT", "NAN"});
    expect_at2_error("dt_inf.at2", at2_text(kUnitsG, "6  1e999  NPTS, DT", kSixValues), {":4:", "DT", "1E999"});
}

TEST(GroundMotion, At2NonNumericTokenNamesLineAndToken) {
    const std::string values = "   0.1E-01  -0.2E-01   0.3E-01   0.4E-01  -0.5E-01\n   1.0abc\n";
    expect_at2_error("token.at2", at2_text(kUnitsG, kOlderLine4, values), {"token.at2:6:", "'1.0abc'"});
    expect_at2_error("text.at2", at2_text(kUnitsG, kOlderLine4, "0.1 0.2 0.3\nEND OF DATA\n"),
                     {"text.at2:6:", "'END'"});
}

TEST(GroundMotion, At2CountMismatchGivesBothCounts) {
    const std::string five = "   0.1E-01  -0.2E-01   0.3E-01   0.4E-01  -0.5E-01\n";
    expect_at2_error("too_few.at2", at2_text(kUnitsG, kOlderLine4, five), {"NPTS = 6", "5 value", "truncated"});
    expect_at2_error("too_many.at2", at2_text(kUnitsG, kOlderLine4, kSixValues + "  0.7E-01\n"),
                     {"NPTS = 6", "7 value", "too many"});
    expect_at2_error("no_values.at2", at2_text(kUnitsG, kOlderLine4, ""), {"NPTS = 6", "0 value"});
}

TEST(GroundMotion, At2NonFiniteValueIsInputError) {
    for (const std::string bad : {"nan", "inf", "-INF", "1.0E+999"}) {
        SCOPED_TRACE(bad);
        expect_at2_error("nonfinite.at2", at2_text(kUnitsG, kOlderLine4, "0.1 0.2 0.3 0.4 0.5\n" + bad + "\n"),
                         {":6:", "'" + bad + "'", "not finite"});
    }
}

// --- two-column files ---------------------------------------------------------------------------------------------

TEST(GroundMotion, TwoColumnSkipsCommentsAndAcceptsSeparators) {
    const std::string text =
        "# time [s]  acceleration\n"
        "\n"
        "0.0 0.1\n"
        "0.5,\t-0.2   # trailing comment\n"
        "   \t\n"
        "  1.25 ,0.3\r\n"
        "# the end\n";
    const GroundMotion m = read_two_column(temp_file("two.txt", text), AccelUnits::m_per_s2);
    EXPECT_EQ(m.sample_times(), (std::vector<double>{0.0, 0.5, 1.25}));
    EXPECT_EQ(m.sample_values(), (std::vector<double>{0.1, -0.2, 0.3}));
    EXPECT_EQ(m.duration(), 1.25);
}

TEST(GroundMotion, TwoColumnConvertsUnits) {
    const std::string path = temp_file("two_units.txt", "0 100\n0.01 -250\n");
    EXPECT_NEAR(read_two_column(path, AccelUnits::cm_per_s2).sample_values()[1], -2.5, kRoundoff);
    EXPECT_NEAR(read_two_column(path, AccelUnits::g).sample_values()[0], 100.0 * kG0, kRoundoff * 100.0 * kG0);
}

TEST(GroundMotion, TwoColumnErrorsNameTheLine) {
    expect_two_column_error("one_field.txt", "# c\n0 0\n0.01\n0.02 0\n", {"one_field.txt:3:", "2 numbers", "1 field"});
    expect_two_column_error("three_fields.txt", "0 0\n0.01 1 2\n", {"three_fields.txt:2:", "3 field"});
    expect_two_column_error("token.txt", "0 0\n0.01 1.0abc\n", {"token.txt:2:", "'1.0abc'"});
    expect_two_column_error("nan.txt", "0 0\n0.01 nan\n", {"nan.txt:2:", "'nan'", "not finite"});
    expect_two_column_error("inf_time.txt", "0 0\ninf 1\n", {"inf_time.txt:2:", "'inf'", "not finite"});
    expect_two_column_error("repeat.txt", "0 0\n0.01 1\n\n0.01 2\n", {"repeat.txt:4:", "not after", "(line 2)"});
    expect_two_column_error("decrease.txt", "0 0\n0.02 1\n0.01 2\n", {"decrease.txt:3:", "0.01"});
    expect_two_column_error("negative.txt", "-0.01 0\n0 1\n", {"negative.txt:1:", "-0.01"});
    expect_two_column_error("single.txt", "# only one\n0 1\n", {"single.txt", "1 data line", "at least 2"});
    expect_two_column_error("comments_only.txt", "# nothing\n\n", {"comments_only.txt", "0 data line"});
}

// --- sampled records ----------------------------------------------------------------------------------------------

TEST(GroundMotion, SampledValidatesInput) {
    expect_input_error([] { GroundMotion::sampled({0.0, 1.0}, {1.0}, "r"); }, {"2 times", "1 acceleration"});
    expect_input_error([] { GroundMotion::sampled({0.0}, {1.0}, "r"); }, {"1 sample"});
    expect_input_error([] { GroundMotion::sampled({0.0, 1.0, 1.0}, {1.0, 2.0, 3.0}, "r"); }, {"increase", "sample 2"});
    expect_input_error([] { GroundMotion::sampled({0.0, 1.0}, {1.0, NAN}, "r"); }, {"finite", "nan"});
    expect_input_error([] { GroundMotion::sampled({0.0, INFINITY}, {1.0, 1.0}, "r"); }, {"finite", "inf"});
    expect_input_error([] { GroundMotion::sampled({-1.0, 1.0}, {1.0, 1.0}, "r"); }, {"0 or later", "-1"});
}

TEST(GroundMotion, InterpolationIsExactForLinearFunctionAndZeroOutside) {
    const auto line = [](double t) { return 2.0 - 3.0 * t; };
    // Uneven spacing (binary-search lookup) and even spacing (O(1) lookup).
    const std::vector<std::vector<double>> grids{{0.0, 0.1, 0.25, 0.7, 1.0}, {0.0, 0.25, 0.5, 0.75, 1.0}};
    for (const auto& times : grids) {
        std::vector<double> values;
        for (double t : times) values.push_back(line(t));
        const GroundMotion m = GroundMotion::sampled(times, values, "line");
        for (double t : {0.0, 0.01, 0.1, 0.2, 0.25, 0.4, 0.5, 0.69, 0.7, 0.93, 1.0})
            EXPECT_NEAR(m(t), line(t), kRoundoff) << t;
        for (double t : times) EXPECT_EQ(m(t), line(t)) << "a sample is returned exactly at its time " << t;
        EXPECT_EQ(m(-1e-12), 0.0);
        EXPECT_EQ(m(-5.0), 0.0);
        EXPECT_EQ(m(1.0 + 1e-12), 0.0);
        EXPECT_EQ(m(7.0), 0.0);
        EXPECT_EQ(m.breakpoints(), times);
        EXPECT_EQ(m.duration(), 1.0);
    }
}

TEST(GroundMotion, EvenSpacingLookupMatchesReference) {
    // 0.01 s is not a binary fraction, so i * dt and t / dt round: the O(1) guess must be corrected at the edges.
    std::vector<double> times, values;
    for (int i = 0; i <= 2000; ++i) {
        times.push_back(0.01 * i);
        values.push_back(std::sin(0.37 * i) + 0.1 * (i % 7));
    }
    const GroundMotion m = GroundMotion::sampled(times, values, "even");
    for (std::size_t i = 0; i + 1 < times.size(); ++i) {
        for (double x : {times[i], std::nextafter(times[i], 1e9), 0.5 * (times[i] + times[i + 1]),
                         std::nextafter(times[i + 1], -1e9)})
            EXPECT_NEAR(m(x), reference_interpolation(times, values, x), kInterpolationsApart) << x;
    }
    EXPECT_EQ(m(times.back()), values.back());
}

// The integrator's stages read a record through its linear pieces (simulate.cpp): each piece must hold its time and
// give the interpolated value, and there must be none where the record is not sampled.
TEST(GroundMotion, LinearPiecesReproduceTheInterpolation) {
    std::vector<double> times, values;
    for (int i = 0; i <= 400; ++i) {
        times.push_back(0.5 + 0.01 * i);  // a record starting late: nothing before 0.5 s
        values.push_back(std::sin(0.37 * i) + 0.1 * (i % 7));
    }
    const GroundMotion m = GroundMotion::sampled(times, values, "even");
    for (std::size_t i = 0; i + 1 < times.size(); ++i) {
        for (double x : {times[i], 0.3 * times[i] + 0.7 * times[i + 1], std::nextafter(times[i + 1], -1e9)}) {
            const std::optional<GroundMotion::LinearPiece> p = m.linear_piece(x);
            ASSERT_TRUE(p.has_value()) << x;
            EXPECT_LE(p->start, x);
            EXPECT_GE(p->end, x);
            EXPECT_NEAR(p->value + p->slope * (x - p->start), m(x), kInterpolationsApart) << x;
        }
    }
    const std::optional<GroundMotion::LinearPiece> last = m.linear_piece(times.back());
    ASSERT_TRUE(last.has_value());
    EXPECT_NEAR(last->value + last->slope * (times.back() - last->start), values.back(), kInterpolationsApart);
    for (double x : {0.0, 0.499, std::nextafter(times.back(), 1e9), 10.0, double(NAN)})
        EXPECT_FALSE(m.linear_piece(x).has_value()) << x;
    EXPECT_FALSE(cosine_pulse(-2.0, 0.5).linear_piece(0.1).has_value());  // analytic: evaluated as it is
    const std::optional<GroundMotion::LinearPiece> none = GroundMotion::none().linear_piece(3.0);
    ASSERT_TRUE(none.has_value());
    EXPECT_EQ(none->value + none->slope * (1e4 - none->start), 0.0);
    EXPECT_EQ(none->value + none->slope * (-1e4 - none->start), 0.0);
}

TEST(GroundMotion, RecordStartingLateIsZeroBeforeFirstSample) {
    const GroundMotion m = GroundMotion::sampled({1.0, 2.0, 3.0}, {4.0, 5.0, 6.0}, "late");
    EXPECT_EQ(m(0.0), 0.0);
    EXPECT_EQ(m(0.999), 0.0);
    EXPECT_EQ(m(1.0), 4.0);
    EXPECT_NEAR(m(2.5), 5.5, kRoundoff);
    EXPECT_EQ(m.duration(), 3.0);
}

TEST(GroundMotion, NanTimeIsNotMaskedAsZero) {
    const GroundMotion m = GroundMotion::sampled({0.0, 1.0}, {1.0, 1.0}, "r");
    EXPECT_TRUE(std::isnan(m(NAN)));
}

// --- analytic signals and none ------------------------------------------------------------------------------------

TEST(GroundMotion, AnalyticBreakpointsAreSortedDeduplicatedWithEnds) {
    const GroundMotion m =
        GroundMotion::analytic([](double t) { return t; }, 2.0, {1.5, 0.5, 1.5, 2.0}, {2.0, {}}, "ramp");
    EXPECT_EQ(m.breakpoints(), (std::vector<double>{0.0, 0.5, 1.5, 2.0}));
    EXPECT_EQ(m(1.25), 1.25);
    EXPECT_EQ(m(2.0), 2.0);
    EXPECT_EQ(m(2.0 + 1e-12), 0.0);
    EXPECT_EQ(m(-1e-12), 0.0);
    EXPECT_NEAR(m.pga(), 2.0, kStatedPeakTol);
    EXPECT_TRUE(m.sample_times().empty());
    EXPECT_EQ(m.name(), "ramp");
}

TEST(GroundMotion, AnalyticValidatesArguments) {
    const auto one = [](double) { return 1.0; };
    expect_input_error([] { GroundMotion::analytic(nullptr, 1.0, {}, {1.0, {}}, "f"); }, {"'f'", "no function"});
    expect_input_error([&] { GroundMotion::analytic(one, 0.0, {}, {1.0, {}}, "f"); }, {"duration", "got 0"});
    expect_input_error([&] { GroundMotion::analytic(one, NAN, {}, {1.0, {}}, "f"); }, {"duration", "nan"});
    expect_input_error([&] { GroundMotion::analytic(one, 1.0, {1.5}, {1.0, {}}, "f"); }, {"breakpoint", "1.5"});
    expect_input_error([&] { GroundMotion::analytic(one, 1.0, {-0.5}, {1.0, {}}, "f"); }, {"breakpoint", "-0.5"});
    expect_input_error([&] { GroundMotion::analytic(one, 1.0, {}, {NAN, {}}, "f"); }, {"peak", "nan"});
    expect_input_error([&] { GroundMotion::analytic(one, 1.0, {}, {-1.0, {}}, "f"); }, {"peak", "-1"});
}

TEST(GroundMotion, NoneIsZeroEverywhere) {
    const GroundMotion m = GroundMotion::none();
    EXPECT_TRUE(m.is_zero());
    EXPECT_EQ(m.duration(), 0.0);
    for (double t : {-1.0, 0.0, 0.5, 100.0}) EXPECT_EQ(m(t), 0.0);
    EXPECT_EQ(m.pga(), 0.0);
    EXPECT_TRUE(m.scaled(3.0).is_zero());
    expect_input_error([&] { m.scaled_to_pga(1.0); }, {"PGA", "got 0"});
}

// --- scaling ------------------------------------------------------------------------------------------------------

TEST(GroundMotion, ScaledMultipliesSamplesAndFunctions) {
    const GroundMotion r = GroundMotion::sampled({0.0, 1.0, 2.0}, {1.0, -3.0, 2.0}, "rec");
    const GroundMotion r2 = r.scaled(-0.5);
    EXPECT_EQ(r2.sample_values(), (std::vector<double>{-0.5, 1.5, -1.0}));
    EXPECT_EQ(r2.sample_times(), r.sample_times());
    EXPECT_EQ(r2.name(), "rec x -0.5");
    EXPECT_NEAR(r2(0.5), -0.5 * r(0.5), kRoundoff);
    EXPECT_EQ(r2.pga(), 1.5);

    const GroundMotion p = sine_pulse(2.0, 0.4);
    const GroundMotion p3 = p.scaled(3.0);
    EXPECT_NEAR(p3(0.1), 3.0 * p(0.1), kRoundoff);
    EXPECT_EQ(p3.breakpoints(), p.breakpoints());
    EXPECT_EQ(p3.duration(), p.duration());
    EXPECT_EQ(p3(0.5), 0.0);
    EXPECT_EQ(p3.name(), p.name() + " x 3");
}

TEST(GroundMotion, ScaledRejectsNonFiniteFactor) {
    const GroundMotion r = GroundMotion::sampled({0.0, 1.0}, {1.0, 2.0}, "rec");
    expect_input_error([&] { r.scaled(NAN); }, {"scale factor", "'rec'", "nan"});
    expect_input_error([&] { r.scaled(INFINITY); }, {"scale factor", "inf"});
    expect_input_error([&] { sine_pulse(1.0, 1.0).scaled(-INFINITY); }, {"scale factor", "-inf"});
    expect_input_error([&] { GroundMotion::sampled({0.0, 1.0}, {1e300, 2.0}, "big").scaled(1e10); }, {"overflows"});
}

TEST(GroundMotion, ScaledToPgaHitsTarget) {
    const GroundMotion record = read_peer_at2(kDataDir + "/NGA_no_1063_RRS228.AT2");
    const double target = 0.3 * kG0;
    EXPECT_NEAR(record.scaled_to_pga(target).pga(), target, kRoundoff * target);
    EXPECT_NEAR(ricker_wavelet(-4.0, 0.5).scaled_to_pga(target).pga(), target, kStatedPeakTol * target);
}

TEST(GroundMotion, ScaledToPgaRejectsBadTargetOrFlatRecord) {
    const GroundMotion r = GroundMotion::sampled({0.0, 1.0}, {1.0, 2.0}, "rec");
    expect_input_error([&] { r.scaled_to_pga(0.0); }, {"target PGA", "got 0"});
    expect_input_error([&] { r.scaled_to_pga(-1.0); }, {"target PGA", "-1"});
    expect_input_error([&] { r.scaled_to_pga(NAN); }, {"target PGA", "nan"});
    const GroundMotion flat = GroundMotion::sampled({0.0, 1.0}, {0.0, 0.0}, "flat");
    expect_input_error([&] { flat.scaled_to_pga(1.0); }, {"'flat'", "got 0"});
}

// --- synthetic inputs ---------------------------------------------------------------------------------------------

TEST(GroundMotion, SinePulseHasDocumentedShape) {
    const double ap = 1.5, tp = 0.8;
    const GroundMotion m = sine_pulse(ap, tp);
    EXPECT_EQ(m.duration(), tp);
    EXPECT_EQ(m.breakpoints(), (std::vector<double>{0.0, tp}));
    EXPECT_NEAR(m(tp / 4.0), ap, kRoundoff);
    EXPECT_NEAR(m(3.0 * tp / 4.0), -ap, kRoundoff);
    EXPECT_NEAR(m(0.3), ap * std::sin(2.0 * kPi * 0.3 / tp), kRoundoff);
    EXPECT_NEAR(m.pga(), ap, kStatedPeakTol);
    EXPECT_EQ(m(-0.01), 0.0);
    EXPECT_EQ(m(tp + 0.01), 0.0);
}

TEST(GroundMotion, CosinePulseJumpsAtItsEnds) {
    const double ap = -2.0, tp = 0.5;
    const GroundMotion m = cosine_pulse(ap, tp);
    EXPECT_EQ(m.duration(), tp);
    EXPECT_EQ(m.breakpoints(), (std::vector<double>{0.0, tp}));
    EXPECT_EQ(m(0.0), ap);
    EXPECT_NEAR(m(tp / 2.0), -ap, kRoundoff);
    EXPECT_NEAR(m(tp), ap, kRoundoff);
    EXPECT_EQ(m(-1e-9), 0.0);
    EXPECT_EQ(m(tp + 1e-9), 0.0);
    EXPECT_NEAR(m.pga(), std::abs(ap), kStatedPeakTol);
}

// The integrator skips the extra evaluation after a breakpoint only where continuous_at says so: a jump must never
// be called continuous.
TEST(GroundMotion, ContinuityIsClaimedOnlyInsideARecordOrWithoutMotion) {
    const GroundMotion record = GroundMotion::sampled({0.0, 0.01, 0.02, 0.03}, {1.0, -2.0, 3.0, 4.0}, "r");
    EXPECT_TRUE(record.continuous_at(0.01));
    EXPECT_TRUE(record.continuous_at(0.02));
    EXPECT_FALSE(record.continuous_at(0.0));   // from 0 before the record to 1 m/s^2
    EXPECT_FALSE(record.continuous_at(0.03));  // from 4 m/s^2 to 0 after it
    const GroundMotion pulse = cosine_pulse(-2.0, 0.5);
    for (double t : pulse.breakpoints()) EXPECT_FALSE(pulse.continuous_at(t));
    EXPECT_TRUE(GroundMotion::none().continuous_at(1.0));
}

TEST(GroundMotion, RickerWaveletPeaksAtItsCentre) {
    const double ap = 3.0, tp = 0.4;
    const GroundMotion m = ricker_wavelet(ap, tp);
    EXPECT_NEAR(m.duration(), 3.0 * tp, kRoundoff);
    EXPECT_EQ(m(1.5 * tp), ap);
    EXPECT_NEAR(m.pga(), ap, kStatedPeakTol);
    // Symmetric about the centre; the zero crossings are where 2 pi^2 f^2 tau^2 = 1.
    EXPECT_NEAR(m(1.5 * tp - 0.1), m(1.5 * tp + 0.1), kRoundoff);
    EXPECT_NEAR(m(1.5 * tp + tp / (kPi * std::sqrt(2.0))), 0.0, kRoundoff);
    EXPECT_EQ(m.breakpoints().front(), 0.0);
    EXPECT_NEAR(m.breakpoints().back(), 3.0 * tp, kRoundoff);
    EXPECT_EQ(m(-0.01), 0.0);
    EXPECT_EQ(m(3.0 * tp + 0.01), 0.0);
}

// A scan on a fixed grid lands on a fast harmonic's zeros (a 1 ms period every 0.5 ms: 7.7e-12 g of 0.5 g, and
// --pga 0.5 then scaled it by 6.5e10): the peak is the amplitude, stated, and the extrema are where |a| is it.
TEST(GroundMotion, AFastHarmonicsPgaIsItsAmplitudeAndItsExtremaAreItsPeaks) {
    const double ap = 0.5 * 9.80665, period = 1e-3;
    const GroundMotion h = harmonic(ap, period, 10.0);
    EXPECT_EQ(h.pga(), ap);
    EXPECT_EQ(h.scaled_to_pga(2.0 * ap).pga(), 2.0 * ap);
    double t = 0.0;
    for (int k = 0; k < 5; ++k) {
        t = h.next_extremum(t);
        EXPECT_NEAR(t, (0.25 + 0.5 * k) * period, kRoundoff);
        EXPECT_NEAR(std::abs(h(t)), ap, kRoundoff * ap) << "extremum " << k;
    }
    // Ended before its first peak: the peak is where it stops, sin(2 pi 0.1) of the amplitude.
    const GroundMotion short_one = harmonic(1.0, 1.0, 0.1);
    EXPECT_NEAR(short_one.pga(), std::sin(2.0 * 3.141592653589793 * 0.1), kRoundoff);
    EXPECT_EQ(short_one.next_extremum(0.0), INFINITY);
    // A sine pulse's at T/4 and 3T/4, a cosine pulse's at T/2 (its ends are breakpoints); none after.
    const GroundMotion sine = sine_pulse(1.0, 2.0), cosine = cosine_pulse(1.0, 2.0);
    EXPECT_NEAR(sine.next_extremum(0.0), 0.5, kRoundoff);
    EXPECT_NEAR(sine.next_extremum(0.5), 1.5, kRoundoff);
    EXPECT_EQ(sine.next_extremum(1.5), INFINITY);
    EXPECT_NEAR(cosine.next_extremum(0.0), 1.0, kRoundoff);
    EXPECT_EQ(cosine.next_extremum(1.0), INFINITY);
    // A harmonic of more than 1e6 cycles is refused (the rest phase looks at each extremum).
    EXPECT_THROW(harmonic(1.0, 1e-8, 600.0), InputError);
    // The Ricker wavelet's: its side lobes (x = 1.5) and its centre; none after the last.
    const GroundMotion r = ricker_wavelet(2.0, 1.0);
    const double lobe = std::sqrt(1.5) / 3.141592653589793;
    EXPECT_NEAR(r.next_extremum(0.0), 1.5 - lobe, kRoundoff);
    EXPECT_NEAR(r.next_extremum(1.5 - lobe), 1.5, kRoundoff);
    EXPECT_NEAR(r.next_extremum(1.5), 1.5 + lobe, kRoundoff);
    EXPECT_EQ(r.next_extremum(1.5 + lobe), INFINITY);
    // Records and no motion have none (a record's samples are its breakpoints).
    EXPECT_EQ(GroundMotion::sampled({0.0, 1.0}, {1.0, -1.0}, "r").next_extremum(0.0), INFINITY);
    EXPECT_EQ(GroundMotion::none().next_extremum(0.0), INFINITY);
}

TEST(GroundMotion, HarmonicAndConstantMotion) {
    const GroundMotion h = harmonic(0.5, 0.2, 1.0);
    EXPECT_EQ(h.duration(), 1.0);
    EXPECT_NEAR(h(0.05), 0.5, kRoundoff);
    EXPECT_NEAR(h(0.85), 0.5, kRoundoff);
    EXPECT_NEAR(h.pga(), 0.5, kStatedPeakTol);
    EXPECT_EQ(h(1.01), 0.0);

    const GroundMotion c = constant_motion(-0.7, 2.0);
    EXPECT_EQ(c.duration(), 2.0);
    EXPECT_EQ(c(0.0), -0.7);
    EXPECT_EQ(c(2.0), -0.7);
    EXPECT_EQ(c(2.0 + 1e-9), 0.0);
    EXPECT_EQ(c(-1e-9), 0.0);
    EXPECT_EQ(c.pga(), 0.7);
    EXPECT_EQ(c.breakpoints(), (std::vector<double>{0.0, 2.0}));
}

TEST(GroundMotion, SyntheticGeneratorsValidateArguments) {
    expect_input_error([] { sine_pulse(NAN, 1.0); }, {"amplitude", "nan"});
    expect_input_error([] { cosine_pulse(INFINITY, 1.0); }, {"amplitude", "inf"});
    expect_input_error([] { ricker_wavelet(1.0, 0.0); }, {"period", "got 0"});
    expect_input_error([] { sine_pulse(1.0, -0.5); }, {"period", "-0.5"});
    expect_input_error([] { cosine_pulse(1.0, INFINITY); }, {"period", "inf"});
    expect_input_error([] { harmonic(1.0, 0.2, 0.0); }, {"duration", "got 0"});
    expect_input_error([] { harmonic(1.0, NAN, 1.0); }, {"period", "nan"});
    expect_input_error([] { constant_motion(1.0, -1.0); }, {"duration", "-1"});
    expect_input_error([] { constant_motion(NAN, 1.0); }, {"amplitude", "nan"});
    EXPECT_EQ(sine_pulse(0.0, 1.0).pga(), 0.0);  // a zero amplitude is allowed
}

// --- units --------------------------------------------------------------------------------------------------------

TEST(GroundMotion, ParsesUnitNames) {
    EXPECT_EQ(parse_units("g"), AccelUnits::g);
    EXPECT_EQ(parse_units("G"), AccelUnits::g);
    EXPECT_EQ(parse_units("m/s2"), AccelUnits::m_per_s2);
    EXPECT_EQ(parse_units("m/s^2"), AccelUnits::m_per_s2);
    EXPECT_EQ(parse_units("cm/s2"), AccelUnits::cm_per_s2);
    EXPECT_EQ(parse_units("cm/s^2"), AccelUnits::cm_per_s2);
    EXPECT_EQ(parse_units("gal"), AccelUnits::cm_per_s2);
    expect_input_error([] { parse_units("furlong/fortnight^2"); }, {"'furlong/fortnight^2'", "g, m/s2"});
    expect_input_error([] { parse_units(""); }, {"''"});
}

TEST(GroundMotion, ConvertsUnitsToMetresPerSecondSquared) {
    EXPECT_EQ(to_m_per_s2(AccelUnits::g), kG0);
    EXPECT_EQ(to_m_per_s2(AccelUnits::m_per_s2), 1.0);
    EXPECT_EQ(to_m_per_s2(AccelUnits::cm_per_s2), 0.01);
}

// quiet_after: a record is linear between its samples, so |a| may exceed a level up to the sample after the last one
// above it, and not past it; an analytic signal is not scanned (its duration); no motion is quiet at once.
TEST(GroundMotion, QuietAfterIsTheSampleAfterTheLastOneAboveTheLevel) {
    const GroundMotion m = GroundMotion::sampled({0.0, 0.5, 1.0, 1.5, 2.0}, {0.0, -3.0, 1.0, 2.5, 0.5}, "m");
    EXPECT_EQ(m.quiet_after(2.0), 2.0);   // 2.5 at 1.5 s: quiet from the next sample
    EXPECT_EQ(m.quiet_after(2.8), 1.0);   // only -3 at 0.5 s exceeds it
    EXPECT_EQ(m.quiet_after(3.0), 0.0);   // nothing exceeds it
    EXPECT_EQ(m.quiet_after(0.1), 2.0);   // the last sample exceeds it: quiet from the record's end
    EXPECT_EQ(GroundMotion::none().quiet_after(0.0), 0.0);
    const GroundMotion pulse = GroundMotion::analytic([](double) { return 0.0; }, 3.0, {}, {0.0, {}}, "zero");
    EXPECT_EQ(pulse.quiet_after(1.0), 3.0);
}

}  // namespace
}  // namespace vssw
