// The record readers beyond PEER AT2 and two columns (analytic/ground_motion.hpp, RecordFormat): accelerations alone
// at a given step (OpenSees `Path -dt`) and tables with a header row. The same record written in each format reads
// back to the same samples, bit for bit; every malformed file is refused with a message naming the line or the
// setting, never read silently short.
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "analytic/error.hpp"
#include "analytic/ground_motion.hpp"

namespace {

using vssw::AccelUnits;
using vssw::GroundMotion;
using vssw::InputError;
using vssw::parse_record;
using vssw::RecordFormat;

const std::string kRinaldi = std::string(VSSW_DATA_DIR) + "/NGA_no_1063_RRS228.AT2";
const AccelUnits kMetres = AccelUnits::m_per_s2;  // the samples written back in m/s^2: read with no conversion

// The shipped Rinaldi record's samples written in another format: "%.17g" round-trips every double exactly.
struct Written {
    GroundMotion original = vssw::read_record(kRinaldi);
    std::string accelerations(const char* separator, int per_line) const {
        std::string text = "# Rinaldi, accelerations only, m/s^2\n";
        const auto& a = original.sample_values();
        for (std::size_t i = 0; i < a.size(); ++i)
            text += fmt::format("{:.17g}{}", a[i], (i + 1) % per_line == 0 || i + 1 == a.size() ? "\n" : separator);
        return text;
    }
    std::string table(const std::string& header, bool with_time) const {
        std::string text = header + "\n";
        const auto& t = original.sample_times();
        const auto& a = original.sample_values();
        for (std::size_t i = 0; i < a.size(); ++i)
            text += with_time ? fmt::format("{:.17g},{:.17g},7\n", t[i], a[i]) : fmt::format("7,{:.17g}\n", a[i]);
        return text;
    }
};

void expect_same_samples(const GroundMotion& a, const GroundMotion& b) {
    EXPECT_EQ(a.sample_times(), b.sample_times());
    EXPECT_EQ(a.sample_values(), b.sample_values());
}

std::string message_of(const std::string& text, const RecordFormat& format, const AccelUnits* units = &kMetres) {
    try {
        parse_record(text, "rec.txt", units, format);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(RecordFormats, AccelerationsAtAGivenStepReadAsTheAt2RecordDoes) {
    const Written w;
    const double dt = w.original.sample_times()[1];  // 0.01 s, exactly as the AT2 reader built the times
    for (int per_line : {1, 5, 8}) {
        SCOPED_TRACE(per_line);
        RecordFormat format;
        format.dt = dt;
        expect_same_samples(parse_record(w.accelerations(" ", per_line), "r.txt", &kMetres, format), w.original);
        expect_same_samples(parse_record(w.accelerations(",", per_line), "r.csv", &kMetres, format), w.original);
    }
}

TEST(RecordFormats, TablesWithAHeaderReadByColumnName) {
    const Written w;
    RecordFormat by_time;
    by_time.time_column = "Time (s)";
    by_time.accel_column = "Acc";
    expect_same_samples(parse_record(w.table("Time (s),Acc,Other", true), "r.csv", &kMetres, by_time), w.original);
    RecordFormat by_step;
    by_step.dt = w.original.sample_times()[1];
    by_step.accel_column = "Acc";
    expect_same_samples(parse_record(w.table("Other,Acc", false), "r.csv", &kMetres, by_step), w.original);
}

TEST(RecordFormats, ATwoColumnTableNeedsNoNames) {
    const GroundMotion m = parse_record("time,acc\n0,0.1\n0.5,0.2\n1.0,-0.1\n", "r.csv", &kMetres);
    EXPECT_EQ(m.sample_times(), (std::vector<double>{0.0, 0.5, 1.0}));
    EXPECT_EQ(m.sample_values(), (std::vector<double>{0.1, 0.2, -0.1}));
    // Naming only the time column of two: the other is the acceleration, whichever comes first.
    RecordFormat time_second;
    time_second.time_column = "time";
    const GroundMotion swapped = parse_record("acc,time\n0.1,0\n0.2,0.5\n", "r.csv", &kMetres, time_second);
    EXPECT_EQ(swapped.sample_times(), (std::vector<double>{0.0, 0.5}));
    EXPECT_EQ(swapped.sample_values(), (std::vector<double>{0.1, 0.2}));
}

TEST(RecordFormats, UnitsApplyToEveryFormat) {
    RecordFormat format;
    format.dt = 0.1;
    const AccelUnits g = AccelUnits::g;
    const GroundMotion m = parse_record("0.5 -0.25\n", "r.txt", &g, format);
    EXPECT_EQ(m.sample_values(), (std::vector<double>{0.5 * vssw::kStandardGravity, -0.25 * vssw::kStandardGravity}));
    EXPECT_EQ(m.sample_times(), (std::vector<double>{0.0, 0.1}));
}

TEST(RecordFormats, MalformedFilesAreRefusedNamingWhatIsWrong) {
    RecordFormat step;
    step.dt = 0.01;
    EXPECT_TRUE(contains(message_of("0.1\n0.2\nabc\n", step), "rec.txt:3: non-numeric value 'abc'"));
    EXPECT_TRUE(contains(message_of("0.1\n", step), "1 sample(s)"));
    RecordFormat bad_step;
    bad_step.dt = -0.01;
    EXPECT_TRUE(contains(message_of("0.1\n0.2\n", bad_step), "record step"));
    // Two numbers a line, the first rising like a time, read with a step: a table of time and acceleration, refused
    // (its times were read as accelerations); two accelerations a line that do not rise so are read in order.
    std::string table, pairs;
    for (int i = 0; i < 12; ++i) {
        table += fmt::format("{} {}\n", 0.02 * i, i % 3 == 0 ? 0.1 : -0.05);
        pairs += fmt::format("{} {}\n", i % 2 == 0 ? 0.1 : -0.1, 0.05 * i);
    }
    EXPECT_TRUE(contains(message_of(table, step), "the first rises line after line, as a time column does"));
    const AccelUnits g = AccelUnits::g;
    EXPECT_EQ(parse_record(pairs, "pairs.txt", &g, step).sample_values().size(), 24u);
    RecordFormat named;
    named.accel_column = "acc";
    EXPECT_TRUE(contains(message_of("t,a\n0,1\n1,2\n", named), "'acc' is not a column of the header (columns: t, a)"));
    EXPECT_TRUE(contains(message_of("0,1\n1,2\n", named), "no header row"));
    EXPECT_TRUE(contains(message_of("t,a,b\n0,1,2\n1,2\n", named), "acceleration column"));
    RecordFormat three;
    three.accel_column = "a";
    EXPECT_TRUE(contains(message_of("t,a,b\n0,1,2\n1,2\n", three), "name the time column"));
    three.time_column = "t";
    EXPECT_TRUE(contains(message_of("t,a,b\n0,1,2\n1,2\n", three), "rec.txt:3: 2 field(s), the header has 3"));
    EXPECT_TRUE(contains(message_of("t,a,b\n0,1,2\n0,2,3\n", three), "rec.txt:3: time 0 is not after"));
    // A named column twice in the header: which one is meant cannot be told (the first was once taken silently).
    EXPECT_TRUE(contains(message_of("t,a,a\n0,1,5\n1,2,4\n", three),
                         "rec.txt:1: acceleration column 'a' names more than one column of the header "
                         "(columns: t, a, a)"));
    RecordFormat both = three;
    both.dt = 0.01;
    EXPECT_TRUE(contains(message_of("t,a,b\n0,1,2\n1,2,3\n", both), "not both"));
    // A first line of numbers and words is a malformed data line, not a header that would drop it unread.
    EXPECT_TRUE(contains(message_of("0.0 abc\n0.1 0.2\n0.2 0.3\n", {}), "rec.txt:1: non-numeric value 'abc'"));
}

TEST(RecordFormats, AnAt2RecordKeepsItsOwnStep) {
    std::ifstream in(kRinaldi);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    RecordFormat step;
    step.dt = 0.02;
    EXPECT_TRUE(contains(message_of(text, step, nullptr), "PEER AT2 record, whose header gives its step"));
}

}  // namespace

namespace {

TEST(RecordFormatsFromTheField, AByteOrderMarkIsNotPartOfTheFirstValue) {
    RecordFormat step;
    step.dt = 0.01;
    const GroundMotion single = parse_record("\xEF\xBB\xBF" "0.5\n0.25\n0.125\n", "r.txt", &kMetres, step);
    EXPECT_EQ(single.sample_values(), (std::vector<double>{0.5, 0.25, 0.125}));  // none dropped as a "header"
    RecordFormat named;
    named.time_column = "time";
    named.accel_column = "acc";
    const GroundMotion table = parse_record("\xEF\xBB\xBF" "time,acc\n0,1\n1,2\n", "r.csv", &kMetres, named);
    EXPECT_EQ(table.sample_times(), (std::vector<double>{0.0, 1.0}));
    const GroundMotion two = parse_record("\xEF\xBB\xBF" "0.0 1\n0.5 2\n", "r.txt", &kMetres);
    EXPECT_EQ(two.sample_values(), (std::vector<double>{1.0, 2.0}));
}

TEST(RecordFormatsFromTheField, ACommaInACommentDoesNotSplitTheLine) {
    const GroundMotion m = parse_record("0.0 1 # start, at rest\n0.5 2\n", "r.txt", &kMetres);
    EXPECT_EQ(m.sample_values(), (std::vector<double>{1.0, 2.0}));
    RecordFormat step;
    step.dt = 0.1;
    const GroundMotion header = parse_record("acc # in m/s2, east\n1\n2\n", "r.txt", &kMetres, step);
    EXPECT_EQ(header.sample_values(), (std::vector<double>{1.0, 2.0}));
}

TEST(RecordFormatsFromTheField, ADecimalCommaIsRefusedNotReadAsTwoValues) {
    RecordFormat step;
    step.dt = 0.01;
    EXPECT_TRUE(contains(message_of("0,0123\n0,0456\n", step), "rec.txt:1: '0123' after a comma looks like a decimal"));
    // Decimals without a leading zero after the comma: read as 0 and 5, or 1 and 25, they were a wrong record.
    EXPECT_TRUE(contains(message_of("0,5\n0,7\n", step), "rec.txt:1: '0,5' looks like a decimal comma"));
    EXPECT_TRUE(contains(message_of("0.1 0.2\n-1,25\n", step), "rec.txt:2: '-1,25' looks like a decimal comma"));
    // Decimals with points and commas between them are read as they are.
    EXPECT_EQ(parse_record("0.5,0.7\n-1.25,2\n", "r.txt", &kMetres, step).sample_values(),
              (std::vector<double>{0.5, 0.7, -1.25, 2.0}));
}

}  // namespace
