#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "dslam/eval/json_writer.h"

namespace dslam {
namespace {

TEST(JsonWriter, StringEscapesQuoteBackslashAndControlBytes) {
  EXPECT_EQ(JsonString(""), "\"\"");
  EXPECT_EQ(JsonString("plain/path.txt"), "\"plain/path.txt\"");
  EXPECT_EQ(JsonString("a\"b\\c"), "\"a\\\"b\\\\c\"");
  EXPECT_EQ(JsonString("tab\there\nnl"), "\"tab\\u0009here\\u000anl\"");
  EXPECT_EQ(JsonString(std::string("\x01\x1f", 2)), "\"\\u0001\\u001f\"");
  EXPECT_EQ(JsonString(std::string("nul\0end", 7)), "\"nul\\u0000end\"");
  // DEL and UTF-8 bytes (here "é" = C3 A9) are copied unchanged.
  EXPECT_EQ(JsonString("\x7f\xc3\xa9"), "\"\x7f\xc3\xa9\"");
}

TEST(JsonWriter, NumbersUseSignificantDigitsAndNullForNonFinite) {
  EXPECT_EQ(JsonNumber(0.1, 9), "0.1");
  EXPECT_EQ(JsonNumber(1.0, 9), "1");
  EXPECT_EQ(JsonNumber(1.0 / 3.0, 9), "0.333333333");
  EXPECT_EQ(JsonNumber(0.0027440966012, 9), "0.0027440966");
  EXPECT_EQ(JsonNumber(123456789012.0, 9), "1.23456789e+11");
  EXPECT_EQ(JsonNumber(1e-7, 9), "1e-07");
  EXPECT_EQ(JsonNumber(-2.5, 9), "-2.5");
  EXPECT_EQ(JsonNumber(1234567.0, 6), "1.23457e+06");
  EXPECT_EQ(JsonNumber(18.77884, 6), "18.7788");
  EXPECT_EQ(JsonNumber(478.0, 6), "478");
  EXPECT_EQ(JsonNumber(std::nan(""), 9), "null");
  EXPECT_EQ(JsonNumber(std::numeric_limits<double>::infinity(), 9), "null");
  EXPECT_EQ(JsonNumber(-std::numeric_limits<double>::infinity(), 6), "null");
}

TEST(JsonWriter, SixDigitsMatchTheDefaultOstreamFormat) {
  for (double value : {0.00744232111, 10.5370001, 0.000321, 1e-9, 12345678.9, 0.0, 2.0 / 3.0}) {
    std::ostringstream stream;
    stream << value;
    EXPECT_EQ(JsonNumber(value, 6), stream.str()) << value;
  }
}

TEST(JsonWriter, FlatObjectKeepsMemberOrder) {
  JsonObject object;
  object.AddString("name", "x\"y")
      .AddInteger("count", 42)
      .AddInteger("negative", -7)
      .AddNumber("ratio", 0.25, 9)
      .AddNumber("missing", std::nan(""), 9)
      .AddBool("yes", true)
      .AddBool("no", false);
  EXPECT_EQ(object.ToString(),
            "{\n"
            "  \"name\": \"x\\\"y\",\n"
            "  \"count\": 42,\n"
            "  \"negative\": -7,\n"
            "  \"ratio\": 0.25,\n"
            "  \"missing\": null,\n"
            "  \"yes\": true,\n"
            "  \"no\": false\n"
            "}");
}

TEST(JsonWriter, EmptyObjectIsBraces) { EXPECT_EQ(JsonObject().ToString(), "{}"); }

TEST(JsonWriter, NestedObjectsAreIndentedPerLevel) {
  JsonObject inner;
  inner.AddInteger("depth", 2).AddObject("empty", JsonObject());
  JsonObject middle;
  middle.AddString("text", "line\nbreak").AddObject("inner", inner);
  JsonObject outer;
  outer.AddObject("middle", middle).AddNumber("after", 1.5, 6);
  EXPECT_EQ(outer.ToString(),
            "{\n"
            "  \"middle\": {\n"
            "    \"text\": \"line\\u000abreak\",\n"
            "    \"inner\": {\n"
            "      \"depth\": 2,\n"
            "      \"empty\": {}\n"
            "    }\n"
            "  },\n"
            "  \"after\": 1.5\n"
            "}");
}

TEST(JsonWriter, KeysAreEscaped) {
  JsonObject object;
  object.AddInteger("a\"b", 1);
  EXPECT_EQ(object.ToString(), "{\n  \"a\\\"b\": 1\n}");
}

TEST(JsonWriter, WriteJsonFileAddsNewlineAndReportsUnwritablePaths) {
  const std::string path = ::testing::TempDir() + "dslam_json_writer_test.json";
  JsonObject object;
  object.AddInteger("frames", 9);
  WriteJsonFile(path, object);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "{\n  \"frames\": 9\n}\n");
  std::remove(path.c_str());
  EXPECT_THROW(WriteJsonFile("/nonexistent_dslam_dir/out.json", object), std::runtime_error);
}

}  // namespace
}  // namespace dslam
