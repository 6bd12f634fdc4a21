#pragma once
// A small JSON value for test-case files and grading reports. Objects keep their keys in file
// order so a report written back reads in the order a person wrote or expects it.
//
// Values parsed from text remember where they came from (source name, line, column and key path
// such as "cases[2].tolerance"), so a case file with a missing or mistyped member is reported as
//   cases.json:7:20: 'cases[2].tolerance.max_channel_diff' must be a number, not a string
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace gsv {

class Json {
public:
    enum class Type { Null, Bool, Number, String, Array, Object };
    using Array = std::vector<Json>;
    using Member = std::pair<std::string, Json>;
    using Object = std::vector<Member>;

    Json() = default;
    Json(std::nullptr_t) {}
    Json(bool value) : type_(Type::Bool), bool_(value) {}
    template <typename Number,
              std::enable_if_t<std::is_arithmetic_v<Number> && !std::is_same_v<Number, bool>, int> = 0>
    Json(Number value) : type_(Type::Number), number_(static_cast<double>(value)) {}
    // Without these a string literal would convert to bool.
    Json(const char* value) : type_(Type::String), string_(value) {}
    Json(std::string_view value) : type_(Type::String), string_(value) {}
    Json(std::string value) : type_(Type::String), string_(std::move(value)) {}
    Json(Array values) : type_(Type::Array), array_(std::move(values)) {}
    Json(Object members) : type_(Type::Object), object_(std::move(members)) {}

    static Json array() { return Json(Array{}); }
    static Json object() { return Json(Object{}); }

    Type type() const { return type_; }
    bool is_null() const { return type_ == Type::Null; }
    bool is_bool() const { return type_ == Type::Bool; }
    bool is_number() const { return type_ == Type::Number; }
    bool is_string() const { return type_ == Type::String; }
    bool is_array() const { return type_ == Type::Array; }
    bool is_object() const { return type_ == Type::Object; }

    // These throw gsv::Error naming this value's source and key path when the type is wrong.
    bool as_bool() const;
    double as_number() const;
    const std::string& as_string() const;
    const Array& as_array() const;
    Array& as_array();
    const Object& as_object() const;
    Object& as_object();

    // Elements of an array or members of an object; 0 for anything else.
    std::size_t size() const;
    // Array element; throws gsv::Error naming the path when this is not an array or i is out of range.
    const Json& at(std::size_t index) const;

    // The member named key, or nullptr when this is not an object or has no such member.
    const Json* find(const std::string& key) const;
    bool contains(const std::string& key) const { return find(key) != nullptr; }

    // For building: a null value becomes an empty object, a missing key is appended as null.
    // Throws gsv::Error when this is neither null nor an object.
    Json& operator[](const std::string& key);
    // For building: a null value becomes an empty array. Throws gsv::Error on anything but null or array.
    void push_back(Json value);

    // Required members of an object. Each throws gsv::Error naming the source and the member's key
    // path when this is not an object, the member is missing, or it has the wrong type.
    const Json& member_at(const std::string& key) const;  // any type
    double number_at(const std::string& key) const;
    int int_at(const std::string& key) const;  // a number with no fractional part that fits an int
    bool bool_at(const std::string& key) const;
    std::string string_at(const std::string& key) const;
    const Json& array_at(const std::string& key) const;
    const Json& object_at(const std::string& key) const;

    // Optional members: the fallback when missing (or null), an error when present with the wrong type.
    double number_or(const std::string& key, double fallback) const;
    int int_or(const std::string& key, int fallback) const;
    bool bool_or(const std::string& key, bool fallback) const;
    std::string string_or(const std::string& key, const std::string& fallback) const;

    // Written by nlohmann-json. indent > 0: one member or element per line, nested by that many
    // spaces; indent <= 0: one line. Members in the order they were added. Integral numbers below
    // 2^53 print without ".0", others as short text that reads back as the same double; NaN
    // and infinities, which JSON cannot express, print as null. Bytes in strings that are not UTF-8
    // are written as U+FFFD, so what is written always parses.
    std::string dump(int indent = 2) const;

    // Structural equality; where a value came from is ignored.
    friend bool operator==(const Json& a, const Json& b);
    friend bool operator!=(const Json& a, const Json& b) { return !(a == b); }

    // Where a parsed value came from; empty source for values built in code.
    const std::string& source_name() const;
    int line() const { return line_; }
    int column() const { return column_; }
    const std::string& key_path() const { return path_; }

private:
    friend class JsonParser;

    [[noreturn]] void fail(const std::string& what) const;
    [[noreturn]] void fail_type(const char* wanted) const;
    const Json& required_member(const std::string& key, const char* wanted) const;
    std::string child_path(const std::string& key) const;

    Type type_ = Type::Null;
    bool bool_ = false;
    double number_ = 0;
    std::string string_;
    Array array_;
    Object object_;

    std::shared_ptr<const std::string> source_;
    int line_ = 0, column_ = 0;
    std::string path_;
};

// Parsed by nlohmann-json (RFC 8259, strict: no comments, no trailing commas, strings must be UTF-8).
// Throws gsv::Error "source_name:line:col: <what is wrong>" on any error, in one line: for a syntax
// error the byte where nlohmann stopped, with its reason; for a duplicate key, a number too large
// for a double or nesting deeper than 256, the first byte of that key, number or bracket; for a
// NUL byte (nowhere allowed; nlohmann would take it for the end), that byte. A value's
// line() and column() are those of its first byte (the opening quote or bracket, the sign or first
// digit). Lines and columns count from 1; columns count bytes, and a leading UTF-8 byte order mark
// is not counted. Duplicate keys in an object are an error: in a hand-written case file the second
// one is almost always a copy-paste mistake.
Json parse_json(std::string_view text, const std::string& source_name);

// Reads and parses a whole file, using its path as the source name. Throws gsv::Error naming the
// file when it cannot be read.
Json read_json_file(const std::filesystem::path& path);

}  // namespace gsv
