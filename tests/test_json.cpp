#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <vector>
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
    CHECK(gsv::Json(0.001).dump() == "0.001");
    CHECK(gsv::Json(1e-5).dump() == "1e-05");
    CHECK(gsv::Json(9007199254740992.0).dump() == "9.007199254740992e+15");
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

TEST_CASE("json: syntax errors name source, line and column in one line", "[unit]") {
    // The place is the byte where nlohmann's lexer stopped (end of input counts as one byte past the
    // text); the reason is nlohmann's, so only its telling part is checked here.
    struct Case {
        const char* text;
        const char* place;
        const char* reason;
    };
    const Case cases[] = {
        {"", "t.json:1:1: ", "unexpected end of input"},
        {"   \n  ", "t.json:2:3: ", "unexpected end of input"},
        {"[1, 2] x", "t.json:1:8: ", "expected end of input"},
        {"{} {}", "t.json:1:4: ", "unexpected '{'; expected end of input"},
        {"{\"a\": 1,}", "t.json:1:9: ", "unexpected '}'; expected string literal"},
        {"[1,\n 2,\n]", "t.json:3:1: ", "unexpected ']'"},
        {"{\n  \"a\": \"abc\n}", "t.json:2:12: ", "control character U+000A (LF) must be escaped"},
        {"\"abc", "t.json:1:5: ", "missing closing quote"},
        {"[\"a\\q\"]", "t.json:1:5: ", "forbidden character after backslash"},
        {"\"a\\u12G4\"", "t.json:1:7: ", "'\\u' must be followed by 4 hex digits"},
        {"\"\\uD83D\"", "t.json:1:8: ", "surrogate U+D800..U+DBFF must be followed by U+DC00..U+DFFF"},
        {"\"\\uD83D\\u0041\"", "t.json:1:13: ", "surrogate U+D800..U+DBFF must be followed by U+DC00..U+DFFF"},
        {"\"\\uDE00\"", "t.json:1:7: ", "surrogate U+DC00..U+DFFF must follow U+D800..U+DBFF"},
        {"\"a\tb\"", "t.json:1:3: ", "control character U+0009 (HT) must be escaped"},
        {"{\"a\" 1}", "t.json:1:6: ", "expected ':'"},
        {"{\"a\": 1 \"b\": 2}", "t.json:1:11: ", "unexpected string literal; expected '}'"},
        {"{a: 1}", "t.json:1:2: ", "invalid literal"},
        {"{\"k\": 1,\n \"k\": 2}", "t.json:2:2: ", "duplicate key 'k'"},
        {"[1 2]", "t.json:1:4: ", "expected ']'"},
        {"[01]", "t.json:1:3: ", "expected ']'"},
        {"[1.]", "t.json:1:4: ", "expected digit after '.'"},
        {"1e", "t.json:1:3: ", "expected '+', '-', or digit after exponent"},
        {"-x", "t.json:1:2: ", "expected digit after '-'"},
        {"+1", "t.json:1:1: ", "invalid literal"},
        {"tru", "t.json:1:4: ", "invalid literal; last read: 'tru'"},
        {"'single'", "t.json:1:1: ", "invalid literal"},
        {"// note\n{}", "t.json:1:1: ", "invalid literal"},
        {"\xEF\xBB\xBF[x]", "t.json:1:2: ", "invalid literal"},  // the byte order mark is not counted
    };
    for (const Case& c : cases) {
        INFO("input: " << c.text);
        const std::string message = parse_error(c.text);
        CHECK(message.rfind(c.place, 0) == 0);
        CHECK(message.find(c.reason) != std::string::npos);
        CHECK(message.find('\n') == std::string::npos);
        CHECK(message.find("json.exception") == std::string::npos);
    }
}

TEST_CASE("json: each value's line and column are those of its first byte", "[unit]") {
    // Numbers make nlohmann read one byte past them, strings end in a quote that may be escaped
    // inside them, and containers span lines: each is placed at its own first byte all the same.
    const std::string text =
        "\xEF\xBB\xBF{\"n\": 12,\"s\" :\"a\\\"b\" , \"t\":true,\r\n"
        "\t\"list\": [-0.5 ,1e3,\"x\",null,[ ],{}],\n"
        "  \"last\"\n"
        "     :\n"
        "  {\"deep\": [[7]]}}";
    const gsv::Json root = gsv::parse_json(text, "p.json");
    struct Expected {
        const gsv::Json* value;
        const char* path;
        int line, column;
    };
    const gsv::Json& list = root.array_at("list");
    const gsv::Json& deep = root.object_at("last").array_at("deep");
    const Expected expected[] = {
        {&root, "", 1, 1},
        {root.find("n"), "n", 1, 7},
        {root.find("s"), "s", 1, 15},
        {root.find("t"), "t", 1, 28},
        {&list, "list", 2, 10},
        {&list.at(0), "list[0]", 2, 11},
        {&list.at(1), "list[1]", 2, 17},
        {&list.at(2), "list[2]", 2, 21},
        {&list.at(3), "list[3]", 2, 25},
        {&list.at(4), "list[4]", 2, 30},
        {&list.at(5), "list[5]", 2, 34},
        {&root.member_at("last"), "last", 5, 3},
        {&deep, "last.deep", 5, 12},
        {&deep.at(0), "last.deep[0]", 5, 13},
        {&deep.at(0).at(0), "last.deep[0][0]", 5, 14},
    };
    for (const Expected& e : expected) {
        INFO("path: " << e.path);
        CHECK(e.value->key_path() == e.path);
        CHECK(e.value->line() == e.line);
        CHECK(e.value->column() == e.column);
        CHECK(e.value->source_name() == "p.json");
    }
    CHECK(root.string_at("s") == "a\"b");
    CHECK(deep.at(0).at(0).as_number() == 7);
    // The same values one per line, each at column 1: the position does not drift over the text.
    const gsv::Json lines = gsv::parse_json("[\n1,\n\"two\",\ntrue,\n[3],\n4.5\n]", "l.json");
    for (std::size_t i = 0; i < lines.size(); ++i) {
        CHECK(lines.at(i).line() == int(i) + 2);
        CHECK(lines.at(i).column() == 1);
    }
}

namespace {

// Whether the byte at value's line and column is the one its kind of value starts with.
bool placed_at_first_byte(const gsv::Json& value, const std::vector<std::size_t>& line_starts, const std::string& text) {
    const std::size_t at = line_starts.at(static_cast<std::size_t>(value.line() - 1)) + value.column() - 1;
    if (value.line() < 1 || value.column() < 1 || at >= text.size()) return false;
    const char c = text[at];
    switch (value.type()) {
        case gsv::Json::Type::Null: return c == 'n';
        case gsv::Json::Type::Bool: return c == 't' || c == 'f';
        case gsv::Json::Type::Number: return c == '-' || (c >= '0' && c <= '9');
        case gsv::Json::Type::String: return c == '"';
        case gsv::Json::Type::Array: return c == '[';
        case gsv::Json::Type::Object: return c == '{';
    }
    return false;
}

std::size_t count_misplaced(const gsv::Json& value, const std::vector<std::size_t>& line_starts, const std::string& text) {
    std::size_t misplaced = placed_at_first_byte(value, line_starts, text) ? 0 : 1;
    if (value.is_array())
        for (const gsv::Json& element : value.as_array()) misplaced += count_misplaced(element, line_starts, text);
    if (value.is_object())
        for (const gsv::Json::Member& member : value.as_object()) misplaced += count_misplaced(member.second, line_starts, text);
    return misplaced;
}

}  // namespace

TEST_CASE("json: in mutated case files every value is placed at its first byte and every error is one line", "[unit]") {
    // A real case file with bytes changed, removed and inserted at random (fixed seed): what parses
    // has each value's line and column on its own first byte; what does not gives one "t.json:L:C:" line.
    const std::string original = gsv::test::read_text(fs::path(GSV_SOURCE_ROOT) / "grader" / "cases" / "lab06.json");
    const std::string alphabet("{}[]:,\" \n\t\\u0123456789eE+-.truefalsenull\0\xff\xc3\xa9", 44);
    std::mt19937 random(7);
    int parsed = 0, refused = 0;
    std::size_t misplaced = 0, bad_messages = 0;
    for (int round = 0; round < 3000; ++round) {
        std::string text = original;
        for (int edit = 0; edit < 3 && !text.empty(); ++edit) {
            const std::size_t at = random() % text.size();
            const char byte = alphabet[random() % alphabet.size()];
            switch (random() % 3) {
                case 0: text[at] = byte; break;
                case 1: text.erase(at, 1 + random() % 3); break;
                default: text.insert(at, 1, byte);
            }
        }
        std::vector<std::size_t> line_starts{0};
        for (std::size_t i = 0; i < text.size(); ++i)
            if (text[i] == '\n') line_starts.push_back(i + 1);
        try {
            const gsv::Json root = gsv::parse_json(text, "t.json");
            ++parsed;
            misplaced += count_misplaced(root, line_starts, text);
        } catch (const gsv::Error& e) {
            ++refused;
            const std::string message = e.what();
            if (message.rfind("t.json:", 0) != 0 || message.find('\n') != std::string::npos || message.size() > 300)
                ++bad_messages;
        }
    }
    CHECK(parsed > 500);  // the mutations leave many files valid, so placement is checked on many
    CHECK(refused > 500);
    CHECK(misplaced == 0);
    CHECK(bad_messages == 0);
}

TEST_CASE("json: hostile input is refused in one short line", "[unit]") {
    // Nesting: 256 levels parse, the 257th bracket is named; objects count as arrays do.
    CHECK(gsv::parse_json(std::string(256, '[') + std::string(256, ']'), "t.json").is_array());
    CHECK(parse_error(std::string(300, '[')) == "t.json:1:257: nesting deeper than 256");
    std::string objects;
    for (int i = 0; i < 300; ++i) objects += "{\"a\":";
    CHECK(parse_error(objects) == "t.json:1:1281: nesting deeper than 256");

    // Numbers beyond a double are named at their first byte; large integers become doubles.
    CHECK(parse_error("1e999") == "t.json:1:1: number overflow parsing '1e999'");
    CHECK(parse_error("[0, -1e999]") == "t.json:1:5: number overflow parsing '-1e999'");
    const std::string huge_integer = "1" + std::string(400, '0');
    const std::string huge_message = parse_error("[" + huge_integer + "]");
    CHECK(huge_message.rfind("t.json:1:2: number overflow parsing '1000", 0) == 0);
    CHECK(huge_message.size() < 120);  // the 401 digits are not all quoted
    CHECK(gsv::parse_json("18446744073709551617", "t.json").as_number() == 18446744073709551616.0);
    CHECK(gsv::parse_json("-9223372036854775809", "t.json").as_number() == -9223372036854775808.0);

    // Invalid UTF-8: a stray byte, a truncated sequence, an overlong encoding, an encoded surrogate.
    for (const char* bad : {"\"\xFF\"", "\"ab\xC3\"", "\"\xC0\x80\"", "\"\xED\xA0\x80\"", "\"\x80\""}) {
        INFO("input: " << bad);
        const std::string message = parse_error(bad);
        CHECK(message.rfind("t.json:1:", 0) == 0);
        CHECK(message.find("ill-formed UTF-8 byte") != std::string::npos);
    }
    CHECK(parse_error("[\xFF]").find("invalid literal") != std::string::npos);

    // NUL bytes: nowhere in JSON text, also not after a complete value (nlohmann alone stops there).
    using namespace std::string_literals;
    CHECK(parse_error("{}\0{\"evil\": 1}"s) == "t.json:1:3: NUL byte: JSON text cannot contain one (write \\u0000 in a string)");
    CHECK(parse_error("[1,\n\"a\0b\"]"s).rfind("t.json:2:3: NUL byte", 0) == 0);

    // A megabyte string that never closes: the message stays one short line.
    const std::string long_error = parse_error("\"" + std::string(1 << 20, 'x'));
    CHECK(long_error.rfind("t.json:1:1048578: ", 0) == 0);
    CHECK(long_error.find("missing closing quote") != std::string::npos);
    CHECK(long_error.size() < 200);
    CHECK(long_error.find('\n') == std::string::npos);
}

TEST_CASE("json: strings that are not UTF-8 are written as U+FFFD and read back", "[unit]") {
    const gsv::Json output = std::string("ok \xFF\xFE end");
    const std::string written = output.dump();
    CHECK(written == "\"ok \xEF\xBF\xBD\xEF\xBF\xBD end\"");
    CHECK(gsv::parse_json(written, "w").as_string() == "ok \xEF\xBF\xBD\xEF\xBF\xBD end");
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
    const std::string bad_message = gsv::test::gsv_error_message([&] { gsv::read_json_file(file); });
    CHECK(bad_message.rfind(file.string() + ":2:14: ", 0) == 0);
    CHECK(bad_message.find("unexpected ','") != std::string::npos);

    const fs::path good = dir / "good.json";
    std::ofstream(good) << "{\"k\": [true]}";
    CHECK(gsv::read_json_file(good).array_at("k").at(0).as_bool());
    std::error_code ignored;
    fs::remove_all(dir, ignored);
}
