// The Table 1 reader (analytic/specimens.hpp): the shipped file holds the 16 specimens with data, and a malformed file
// is refused with its name, the line and the value.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "analytic/error.hpp"
#include "analytic/specimens.hpp"
#include "tests/table1.hpp"

namespace vssw {
namespace {

using testing::table1;

const std::string kHeader = "number,height_m,thickness_m,hinge_ratio,note\n";

std::string write_file(const std::string& name, const std::string& content) {
    const std::string path = ::testing::TempDir() + "vssw_table1_" + name + ".csv";
    std::ofstream(path, std::ios::trunc | std::ios::binary) << content;
    return path;
}

// The message of the InputError that reading the file raises ("" if none).
std::string refusal(const std::string& path) {
    try {
        (void)read_table1(path);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

void expect_refused(const std::string& name, const std::string& content, const std::vector<std::string>& parts) {
    SCOPED_TRACE(name);
    const std::string message = refusal(write_file(name, content));
    ASSERT_NE(message, "") << "accepted";
    EXPECT_NE(message.find("vssw_table1_" + name + ".csv"), std::string::npos) << message;  // the file is named
    for (const std::string& part : parts) EXPECT_NE(message.find(part), std::string::npos) << part << " in " << message;
}

TEST(Table1, TheShippedFileHoldsTheSixteenSpecimensWithData) {
    std::vector<int> numbers;
    for (const Specimen& s : table1()) numbers.push_back(s.number);
    EXPECT_EQ(numbers, (std::vector<int>{1, 2, 3, 5, 6, 7, 8, 9, 10, 11, 13, 14, 15, 16, 17, 18}));  // 4, 12 damaged
    // Their dimensions: Table1.AnglesAndSizeFollowFromHeightThicknessAndHinge (test_wall.cpp) against the printed
    // columns.
    EXPECT_EQ(table1(7).note, "");
    EXPECT_NE(table1(14).note.find("varied"), std::string::npos);  // the table's footnotes are kept
    EXPECT_NE(table1(17).note.find("fractured"), std::string::npos);
}

TEST(Table1, AnAbsentSpecimenIsNamedWithTheOnesThatExist) {
    try {
        (void)table1(4);
        FAIL() << "specimen 4 found";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("no specimen 4"), std::string::npos) << message;
        EXPECT_NE(message.find("1, 2, 3, 5,"), std::string::npos) << message;
    }
}

TEST(Table1, AWellFormedFileIsReadWithBlankLinesAndCrlf) {
    const std::vector<Specimen> t =
        read_table1(write_file("ok", kHeader + "\r\n7,4.88,0.200,0.50,\r\n\n3,4.88,0.356,0.54,a note\r\n"));
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t[0].number, 7);
    EXPECT_EQ(t[0].thickness, 0.2);  // "0.200"
    EXPECT_EQ(t[1].hinge_ratio, 0.54);
    EXPECT_EQ(t[1].note, "a note");
}

TEST(Table1, MalformedFilesAreRefusedNamingTheFileLineAndValue) {
    expect_refused("missing_column", kHeader + "1,4.88,0.356,0.69\n", {":2:", "4 fields, expected 5"});
    expect_refused("extra_column", kHeader + "1,4.88,0.356,0.69,,x\n", {":2:", "6 fields"});
    expect_refused("header_without_note", "number,height_m,thickness_m,hinge_ratio\n1,4.88,0.356,0.69,\n",
                   {":1:", "header"});
    expect_refused("non_numeric", kHeader + "1,4.88,0.356,0.69,\n2,4.88,thick,0.64,\n",
                   {":3:", "thickness_m", "'thick'"});
    expect_refused("trailing_text", kHeader + "1,4.88 m,0.356,0.69,\n", {":2:", "height_m", "'4.88 m'"});
    expect_refused("nan", kHeader + "1,nan,0.356,0.69,\n", {":2:", "'nan'"});
    expect_refused("duplicate_number", kHeader + "1,4.88,0.356,0.69,\n2,4.88,0.356,0.64,\n1,3.05,0.143,0.53,\n",
                   {":4:", "specimen 1 is given twice", "line 2"});
    expect_refused("fractional_number", kHeader + "1.5,4.88,0.356,0.69,\n", {":2:", "whole number", "'1.5'"});
    expect_refused("hinge_out_of_range", kHeader + "1,4.88,0.356,1.2,\n", {":2:", "hinge_ratio", "'1.2'"});
    expect_refused("negative_height", kHeader + "1,-4.88,0.356,0.69,\n", {":2:", "height_m", "'-4.88'"});
    expect_refused("header_only", kHeader, {"no specimen"});
    expect_refused("empty", "", {"no specimen"});
    const std::string missing = ::testing::TempDir() + "vssw_table1_no_such_file.csv";
    EXPECT_NE(refusal(missing).find("cannot open the Table 1 file '" + missing + "'"), std::string::npos);
}

}  // namespace
}  // namespace vssw
