// The study's results files as text: a CSV record read field by field as written by hand here (quotes, doubled
// quotes, a line break in a field, CRLF, a last line without its break), and results.json's rows written as text,
// each the line nlohmann's own dump gives the same row built as a JSON object (the way they were written before).
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "analytic/error.hpp"
#include "io/csv.hpp"
#include "io/json.hpp"
#include "study/results_files.hpp"
#include "study/study_data.hpp"
#include "tests/temp_files.hpp"

namespace {

using vssw::io::read_csv_record;
using Fields = std::vector<std::string>;

TEST(CsvRecord, ReadsQuotesLineBreaksAndCrlfAsWritten) {
    std::istringstream in("a,\"b,c\",\"say \"\"hi\"\"\"\r\n,\"two\nlines\",\r\nlast,,end");
    Fields f;
    ASSERT_TRUE(read_csv_record(in, f));
    EXPECT_EQ(f, (Fields{"a", "b,c", "say \"hi\""}));
    EXPECT_TRUE(in.good());
    ASSERT_TRUE(read_csv_record(in, f));
    EXPECT_EQ(f, (Fields{"", "two\nlines", ""}));
    ASSERT_TRUE(read_csv_record(in, f));
    EXPECT_EQ(f, (Fields{"last", "", "end"}));
    // The last record ended at the end of the input: the stream says so, as its get() would have.
    EXPECT_TRUE(in.eof());
    EXPECT_TRUE(in.fail());
    EXPECT_FALSE(read_csv_record(in, f));
    EXPECT_TRUE(f.empty());
}

TEST(CsvRecord, AQuotedFieldLeftOpenIsRefused) {
    std::istringstream in("a,\"open field\nstill open");
    Fields f;
    EXPECT_THROW(read_csv_record(in, f), vssw::InputError);
}

// The row as the writer did it before: a JSON object built key by key and dumped.
std::string dumped_row(const Fields& header, const Fields& fields) {
    vssw::io::Json row;
    for (std::size_t i = 0; i < header.size(); ++i) {
        const std::string& v = fields[i];
        char* end = nullptr;
        const double x = std::strtod(v.c_str(), &end);
        const bool number = !v.empty() && *end == '\0';
        const bool numeric = header[i] == "height" || header[i] == "hinge" || header[i] == "value";
        if (v.empty()) row[header[i]] = nullptr;
        else if (header[i] == "case_id") row[header[i]] = static_cast<long>(x);
        else if (!number || !numeric) row[header[i]] = v;
        else row[header[i]] = x;
    }
    return vssw::io::dump_json(row);
}

// results.json from a study folder read back: the manifest's keys, then each row as nlohmann dumps it, every field as
// results.csv gives it (0.30000000000000004 stays so, where the study's levels are made canonical to 12 digits).
TEST(ResultsJson, EachRowIsTheTextNlohmannDumpsForIt) {
    const Fields header = {"case_id", "engine",  "height", "hinge",  "settings",
                           "metric",  "value",   "unit",   "status", "warnings"};
    const std::vector<Fields> rows = {
        {"1", "analytic", "4", "eq15", "", "m", "0.1", "", "ok", ""},
        {"2", "ODE \"double\"", "3.0", "0.7", "dt=0.001", "m", "1e-05", "alpha1", "failed: a \\ b\ttab", "slides"},
        {"3", "bad \xff byte", "2.5", "", "", "m", "123456789.125", "", "ok", ""},
        {"12", "analytic", "0.30000000000000004", "0.5", "", "m", "-2.5e+300", "", "ok", ""},
        {"13", "analytic", "0.3", "0.5", "", "m", "", "", "failed: no value", ""}};
    const vssw::io::Json manifest = {
        {"study", {{"name", "t"}, {"kind", "free"}}},
        {"metrics", vssw::io::Json::array({{{"name", "m"}, {"unit", "alpha1"}}})},
        {"varied", vssw::io::Json::array({"height"})},
        {"runs", vssw::io::Json::array({{{"engine", "analytic"}, {"settings", ""}}})}};
    const vssw::testing::TempDir dir;
    {
        std::ofstream(dir / "manifest.json") << vssw::io::dump_json(manifest, 2) << '\n';
        std::ofstream csv(dir / "results.csv");
        for (std::size_t i = 0; i < header.size(); ++i) csv << (i ? "," : "") << header[i];
        csv << '\n';
        for (const Fields& r : rows)
            for (std::size_t i = 0; i < r.size(); ++i) csv << (i ? "," : "") << vssw::io::csv_field(r[i]) << (i + 1 == r.size() ? "\n" : "");
    }
    std::ostringstream out;
    vssw::study::write_results_json(out, vssw::study::read_study_data(dir.path));
    std::string expected = vssw::io::dump_json(manifest, 2);
    expected.resize(expected.size() - 2);  // "\n}"
    expected += ",\n  \"rows\": [";
    for (std::size_t i = 0; i < rows.size(); ++i) expected += (i ? ",\n    " : "\n    ") + dumped_row(header, rows[i]);
    expected += "\n  ]\n}\n";
    EXPECT_EQ(out.str(), expected);
}

// A value that is not a number is refused by name, not read as none.
TEST(ResultsJson, AValueThatIsNoNumberIsRefused) {
    const vssw::testing::TempDir dir;
    std::ofstream(dir / "manifest.json") << R"({"study": {"name": "t", "kind": "free"}, "metrics": [{"name": "m",
        "unit": ""}], "varied": [], "runs": []})";
    std::ofstream(dir / "results.csv") << "case_id,engine,settings,metric,value,unit,status,warnings\n"
                                          "1,analytic,,m,0.5,,ok,\n1,analytic,,m,half,,ok,\n";
    try {
        (void)vssw::study::read_study_data(dir.path);
        ADD_FAILURE() << "a value 'half' was read";
    } catch (const vssw::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("value 'half' is not a number"), std::string::npos) << e.what();
    }
}

}  // namespace
