#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>

#include "catch.hpp"
#include "common/core/error.h"
#include "common/io/json.h"
#include "test_support.h"

namespace fs = std::filesystem;

namespace {


std::string parse_error(const std::string& text) {
    return gsv::test::gsv_error_message([&] { gsv::parse_json(text, "t.json"); });
}

}  // namespace

TEST_CASE("json: parse, dump and parse again gives the same value", "[unit]") {
    const std::string text = R"({
  "name": "phong",
  "size": [256, 128],
  "tolerance": {"max_channel_diff": 2, "max_differing_fraction": 0.001},
  "enabled": true,
  "skip": false,
  "note": null,
  "scale": -1.5e-3,
  "empty_list": [],
  "empty_object": {}
})";
    const gsv::Json parsed = gsv::parse_json(text, "case.json");
    CHECK(parsed.string_at("name") == "phong");
    CHECK(parsed.array_at("size").at(1).as_number() == 128);
    CHECK(parsed.object_at("tolerance").number_at("max_differing_fraction") == 0.001);
    CHECK(parsed.bool_at("enabled"));
    CHECK(parsed.find("note")->is_null());
    CHECK(parsed.number_at("scale") == -0.0015);
    CHECK(parsed.find("missing") == nullptr);

    const std::string pretty = parsed.dump();
    CHECK(gsv::parse_json(pretty, "dump") == parsed);
    CHECK(gsv::parse_json(parsed.dump(0), "dump") == parsed);
    // Already in canonical form, so a second dump reproduces it byte for byte.
    CHECK(gsv::parse_json(pretty, "dump").dump() == pretty);
}

TEST_CASE("json: dump keeps key order and formats nested values", "[unit]") {
    gsv::Json report;
    report["zeta"] = 1;
    report["alpha"] = "two";
    report["list"].push_back(3);
    report["list"].push_back(gsv::Json::object());
    report["list"].push_back(gsv::Json());
    report["nested"]["flag"] = false;
    CHECK(report.dump() ==
          "{\n"
          "  \"zeta\": 1,\n"
          "  \"alpha\": \"two\",\n"
          "  \"list\": [\n"
          "    3,\n"
          "    {},\n"
          "    null\n"
          "  ],\n"
          "  \"nested\": {\n"
          "    \"flag\": false\n"
          "  }\n"
          "}");
    CHECK(report.dump(0) == R"({"zeta":1,"alpha":"two","list":[3,{},null],"nested":{"flag":false}})");
    CHECK(report.dump(4).find("\n        3,") != std::string::npos);
}

TEST_CASE("json: numbers print as integers when integral and null when not finite", "[unit]") {
    CHECK(gsv::Json(3.0).dump() == "3");
    CHECK(gsv::Json(-42).dump() == "-42");
    CHECK(gsv::Json(-0.0).dump() == "0");
    CHECK(gsv::Json(0.1).dump() == "0.1");
    CHECK(gsv::Json(-2.5).dump() == "-2.5");
    CHECK(gsv::Json(1e20).dump() == "1e+20");
    CHECK(gsv::Json(9007199254740991.0).dump() == "9007199254740991");
    CHECK(gsv::Json(std::numeric_limits<double>::quiet_NaN()).dump() == "null");
    CHECK(gsv::Json(std::numeric_limits<double>::infinity()).dump() == "null");
    CHECK(gsv::Json(-std::numeric_limits<double>::infinity()).dump() == "null");

    // Shortest text that reads back as the same double.
    for (double v : {0.1, 1.0 / 3.0, 6.02214076e23, 5e-324, -1.7976931348623157e308}) {
        const gsv::Json back = gsv::parse_json(gsv::Json(v).dump(), "n");
        CHECK(back.as_number() == v);
    }
    CHECK(gsv::parse_json("-0.5E+2", "n").as_number() == -50);
}

TEST_CASE("json: syntax errors name source, line and column", "[unit]") {
    struct Case {
        const char* text;
        const char* message;
    };
    const Case cases[] = {
        {"", "t.json:1:1: expected a JSON value, found end of input"},
        {"   \n  ", "t.json:2:3: expected a JSON value, found end of input"},
        {"[1, 2] x", "t.json:1:8: unexpected 'x' after the JSON value"},
        {"{} {}", "t.json:1:4: unexpected '{' after the JSON value"},
        {"{\"a\": 1,}", "t.json:1:9: trailing comma before '}' is not allowed in JSON"},
        {"[1,\n 2,\n]", "t.json:3:1: trailing comma before ']' is not allowed in JSON"},
        {"{\n  \"a\": \"abc\n}", "t.json:2:8: unterminated string (line break before the closing quote)"},
        {"\"abc", "t.json:1:1: unterminated string"},
        {"[\"a\\q\"]", "t.json:1:4: invalid escape '\\q' in string"},
        {"\"a\\u12G4\"", "t.json:1:7: expected 4 hex digits after \\u, found 'G'"},
        {"\"\\uD83D\"", "t.json:1:2: high surrogate \\u escape is not followed by a low surrogate"},
        {"\"\\uD83D\\u0041\"", "t.json:1:8: expected a low surrogate \\uDC00-\\uDFFF after a high surrogate"},
        {"\"\\uDE00\"", "t.json:1:2: unpaired low surrogate in \\u escape"},
        {"\"a\tb\"", "t.json:1:3: unescaped control character byte 0x09 in string"},
        {"{\"a\" 1}", "t.json:1:6: expected ':' after member name 'a', found '1'"},
        {"{\"a\": 1 \"b\": 2}", "t.json:1:9: expected ',' or '}' after member 'a', found '\"'"},
        {"{a: 1}", "t.json:1:2: expected a member name in double quotes, found 'a'"},
        {"{\"k\": 1,\n \"k\": 2}", "t.json:2:2: duplicate key 'k'"},
        {"[1 2]", "t.json:1:4: expected ',' or ']' in array, found '2'"},
        {"[01]", "t.json:1:2: leading zeros are not allowed in JSON numbers"},
        {"[1.]", "t.json:1:4: expected a digit after the decimal point, found ']'"},
        {"1e", "t.json:1:3: expected a digit in the exponent, found end of input"},
        {"-x", "t.json:1:2: expected a digit after '-', found 'x'"},
        {"+1", "t.json:1:1: expected a JSON value, found '+'"},
        {"1e999", "t.json:1:1: number 1e999 is out of range"},
        {"tru", "t.json:1:1: invalid literal 'tru' (expected true, false or null)"},
        {"nul", "t.json:1:1: invalid literal 'nul' (expected true, false or null)"},
        {"'single'", "t.json:1:1: unexpected \"'\": JSON strings use double quotes"},
        {"// note\n{}", "t.json:1:1: unexpected '/': JSON does not allow comments"},
        {"\xEF\xBB\xBF[x]", "t.json:1:2: expected a JSON value, found 'x'"},
    };
    for (const Case& c : cases) {
        INFO("input: " << c.text);
        CHECK(parse_error(c.text) == c.message);
    }

    const std::string deep(300, '[');
    CHECK(parse_error(deep) == "t.json:1:257: nesting deeper than 256");
}

TEST_CASE("json: string escapes decode and encode", "[unit]") {
    const gsv::Json parsed =
        gsv::parse_json(R"("q\" b\\ s\/ \b\f\n\r\t \u0001\u001f end")", "s");
    CHECK(parsed.as_string() == "q\" b\\ s/ \b\f\n\r\t \x01\x1f end");
    // '/' needs no escape on output; other control characters become \u00XX.
    CHECK(parsed.dump() == R"("q\" b\\ s/ \b\f\n\r\t \u0001\u001f end")");
    CHECK(gsv::Json(std::string("nul\0byte", 8)).dump() == R"("nul\u0000byte")");
    CHECK(gsv::parse_json(R"("\u0000")", "s").as_string() == std::string(1, '\0'));
}

TEST_CASE("json: unicode escapes become UTF-8, surrogate pairs included", "[unit]") {
    CHECK(gsv::parse_json(R"("\u0041")", "u").as_string() == "A");
    CHECK(gsv::parse_json(R"("\u00e9")", "u").as_string() == "\xC3\xA9");          // e acute
    CHECK(gsv::parse_json(R"("\u20AC")", "u").as_string() == "\xE2\x82\xAC");      // euro sign
    CHECK(gsv::parse_json(R"("\uD83D\uDE00")", "u").as_string() == "\xF0\x9F\x98\x80");  // U+1F600
    CHECK(gsv::parse_json(R"("\uDBFF\uDFFF")", "u").as_string() == "\xF4\x8F\xBF\xBF");  // U+10FFFF
    // Raw UTF-8 passes through both ways unescaped.
    const gsv::Json raw = gsv::parse_json("\"caf\xC3\xA9 \xE2\x82\xAC\"", "u");
    CHECK(raw.as_string() == "caf\xC3\xA9 \xE2\x82\xAC");
    CHECK(raw.dump() == "\"caf\xC3\xA9 \xE2\x82\xAC\"");
}

TEST_CASE("json: required members report the key path and position", "[unit]") {
    const std::string text =
        "{\n"
        "  \"name\": \"lit\",\n"
        "  \"tolerance\": {\"max_channel_diff\": \"2\", \"budget\": 2.5},\n"
        "  \"cases\": [{\"name\": \"a\"}, {\"size\": 3}]\n"
        "}\n";
    const gsv::Json root = gsv::parse_json(text, "cases.json");
    const gsv::Json& tolerance = root.object_at("tolerance");
    CHECK(tolerance.key_path() == "tolerance");
    CHECK(tolerance.line() == 3);
    CHECK(tolerance.column() == 16);

    CHECK(gsv::test::gsv_error_message([&] { tolerance.number_at("max_channel_diff"); }) ==
          "cases.json:3:37: 'tolerance.max_channel_diff' must be a number, not a string");
    CHECK(gsv::test::gsv_error_message([&] { tolerance.number_at("max_differing_fraction"); }) ==
          "cases.json:3:16: 'tolerance.max_differing_fraction' is missing; it must be a number");
    CHECK(gsv::test::gsv_error_message([&] { tolerance.int_at("budget"); }) ==
          "cases.json:3:52: 'tolerance.budget' must be an integer, not 2.5");
    CHECK(gsv::test::gsv_error_message([&] { root.string_at("tolerance"); }) ==
          "cases.json:3:16: 'tolerance' must be a string, not an object");
    CHECK(gsv::test::gsv_error_message([&] { root.array_at("cases").at(1).string_at("name"); }) ==
          "cases.json:4:28: 'cases[1].name' is missing; it must be a string");
    CHECK(gsv::test::gsv_error_message([&] { root.array_at("cases").at(1).bool_at("size"); }) ==
          "cases.json:4:37: 'cases[1].size' must be a boolean, not a number");
    CHECK(gsv::test::gsv_error_message([&] { root.array_at("cases").at(2); }) ==
          "cases.json:4:12: 'cases' has 2 elements; index 2 is out of range");
    CHECK(gsv::test::gsv_error_message([&] { root.find("name")->as_number(); }) ==
          "cases.json:2:11: 'name' must be a number, not a string");
    CHECK(gsv::test::gsv_error_message([&] { gsv::parse_json("[1]", "top.json").number_at("x"); }) ==
          "top.json:1:1: the top-level value must be an object, not an array");
    CHECK(gsv::test::gsv_error_message([&] { root.member_at("absent"); }) == "cases.json:1:1: 'absent' is missing");

    CHECK(root.array_at("cases").at(0).string_at("name") == "a");
    CHECK(root.array_at("cases").at(1).int_at("size") == 3);
}

TEST_CASE("json: optional members fall back only when absent or null", "[unit]") {
    const gsv::Json root = gsv::parse_json(R"({"n": 4, "s": "x", "b": true, "z": null})", "o.json");
    CHECK(root.number_or("n", 1) == 4);
    CHECK(root.number_or("missing", 1.5) == 1.5);
    CHECK(root.int_or("z", 7) == 7);
    CHECK(root.string_or("s", "d") == "x");
    CHECK(root.string_or("missing", "d") == "d");
    CHECK(root.bool_or("b", false));
    CHECK(gsv::test::gsv_error_message([&] { root.bool_or("s", false); }) ==
          "o.json:1:15: 's' must be a boolean, not a string");
}

TEST_CASE("json: values built in code report errors without a position", "[unit]") {
    gsv::Json built;
    built["size"] = "big";
    CHECK(built.source_name().empty());
    CHECK(gsv::test::gsv_error_message([&] { built.number_at("size"); }) == "'size' must be a number, not a string");
    gsv::Json list = gsv::Json::array();
    CHECK(gsv::test::gsv_error_message([&] { list["key"]; }) == "the top-level value must be an object, not an array");
    gsv::Json text = "word";
    CHECK(gsv::test::gsv_error_message([&] { text.push_back(1); }) == "the top-level value must be an array, not a string");
}

TEST_CASE("json: equality ignores object key order but not array order", "[unit]") {
    CHECK(gsv::parse_json(R"({"a": 1, "b": [1, 2]})", "x") ==
          gsv::parse_json(R"({"b": [1, 2], "a": 1})", "y"));
    CHECK(gsv::parse_json("[1, 2]", "x") != gsv::parse_json("[2, 1]", "x"));
    CHECK(gsv::parse_json("1", "x") != gsv::parse_json("\"1\"", "x"));
    CHECK(gsv::parse_json(R"({"a": 1})", "x") != gsv::parse_json(R"({"a": 1, "b": 2})", "x"));
}

TEST_CASE("json: read_json_file names a missing file and uses the path as source name", "[unit]") {
    std::random_device entropy;
    const fs::path dir = fs::temp_directory_path() / ("gsv_test_json_" + std::to_string(entropy()));
    fs::create_directories(dir);
    const fs::path missing = dir / "missing.json";
    CHECK(gsv::test::gsv_error_message([&] { gsv::read_json_file(missing); }) ==
          "cannot read JSON file '" + missing.string() + "': no such file");

    const fs::path file = dir / "bad.json";
    std::ofstream(file) << "{\n  \"a\": [1, 2,, 3]\n}\n";
    CHECK(gsv::test::gsv_error_message([&] { gsv::read_json_file(file); }) ==
          file.string() + ":2:14: expected a JSON value, found ','");

    const fs::path good = dir / "good.json";
    std::ofstream(good) << "{\"k\": [true]}";
    CHECK(gsv::read_json_file(good).array_at("k").at(0).as_bool());
    std::error_code ignored;
    fs::remove_all(dir, ignored);
}
