#include "common/io/json.h"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
#include <locale>
#include <sstream>
#include <system_error>
#include <unordered_set>

#include "common/core/error.h"

namespace gsv {
namespace {

// Streams imbued with the classic locale, unlike strtod and printf, never use a comma as the
// decimal separator whatever locale the program runs in. (std::from_chars/to_chars would do, but
// Apple's libc++ lacks their floating-point forms.)
bool read_double(const std::string& text, double& value) {
    std::istringstream in(text);
    in.imbue(std::locale::classic());
    in >> value;
    return !in.fail() && in.eof();
}

std::string double_text(double value, int significant_digits) {
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out.precision(significant_digits);
    out << value;
    return out.str();
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Parsing (grammar: RFC 8259)

class JsonParser {
public:
    JsonParser(std::string_view text, const std::string& source_name)
        : text_(text), source_(std::make_shared<const std::string>(source_name)) {}

    Json parse_document() {
        static constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
        if (text_.substr(0, kUtf8Bom.size()) == kUtf8Bom) pos_ = line_start_ = bom_size_ = kUtf8Bom.size();
        Json root = parse_value(std::string(), 0);
        skip_whitespace();
        if (pos_ < text_.size())
            fail_at(pos_, "unexpected " + describe(pos_) + " after the JSON value");
        return root;
    }

private:
    // Deep enough for any real case file, shallow enough that recursion cannot overflow the stack.
    static constexpr int kMaxDepth = 256;

    [[noreturn]] void fail_at(std::size_t offset, const std::string& what) const {
        int line = 1;
        std::size_t line_begin = bom_size_;
        for (std::size_t i = 0; i < offset && i < text_.size(); ++i)
            if (text_[i] == '\n') ++line, line_begin = i + 1;
        throw Error(*source_ + ":" + std::to_string(line) + ":" +
                    std::to_string(offset - line_begin + 1) + ": " + what);
    }

    std::string describe(std::size_t offset) const {
        if (offset >= text_.size()) return "end of input";
        const unsigned char c = static_cast<unsigned char>(text_[offset]);
        if (c == '\'') return "\"'\"";
        if (c >= 0x20 && c < 0x7F) return std::string("'") + char(c) + "'";
        static const char* hex = "0123456789ABCDEF";
        return std::string("byte 0x") + hex[c >> 4] + hex[c & 15];
    }

    bool at_end() const { return pos_ >= text_.size(); }
    char peek() const { return at_end() ? '\0' : text_[pos_]; }

    void skip_whitespace() {
        while (!at_end()) {
            const char c = text_[pos_];
            if (c == '\n') {
                ++line_;
                line_start_ = pos_ + 1;
            } else if (c != ' ' && c != '\t' && c != '\r') {
                return;
            }
            ++pos_;
        }
    }

    static std::string member_path(const std::string& parent, const std::string& key) {
        return parent.empty() ? key : parent + "." + key;
    }

    Json parse_value(std::string path, int depth) {
        skip_whitespace();
        if (at_end()) fail_at(pos_, "expected a JSON value, found end of input");
        // Containers span lines, so the position is taken before parsing the value.
        const int start_line = line_;
        const int start_column = static_cast<int>(pos_ - line_start_ + 1);
        Json value;
        switch (text_[pos_]) {
            case '{': value = parse_object(path, depth); break;
            case '[': value = parse_array(path, depth); break;
            case '"': value = Json(parse_string()); break;
            case 't': expect_literal("true"); value = Json(true); break;
            case 'f': expect_literal("false"); value = Json(false); break;
            case 'n': expect_literal("null"); break;
            case '\'': fail_at(pos_, "unexpected " + describe(pos_) + ": JSON strings use double quotes");
            case '/': fail_at(pos_, "unexpected '/': JSON does not allow comments");
            default:
                if (text_[pos_] != '-' && !is_digit(text_[pos_]))
                    fail_at(pos_, "expected a JSON value, found " + describe(pos_));
                value = Json(parse_number());
        }
        value.source_ = source_;
        value.line_ = start_line;
        value.column_ = start_column;
        value.path_ = std::move(path);
        return value;
    }

    void expect_literal(std::string_view word) {
        if (text_.substr(pos_, word.size()) != word) {
            std::size_t end = pos_;
            while (end < text_.size() && end - pos_ < 16 &&
                   std::isalnum(static_cast<unsigned char>(text_[end])))
                ++end;
            fail_at(pos_, "invalid literal '" + std::string(text_.substr(pos_, end - pos_)) +
                              "' (expected true, false or null)");
        }
        pos_ += word.size();
    }

    Json parse_object(const std::string& path, int depth) {
        if (depth >= kMaxDepth) fail_at(pos_, "nesting deeper than " + std::to_string(kMaxDepth));
        ++pos_;  // '{'
        Json object = Json::object();
        std::unordered_set<std::string> keys;
        skip_whitespace();
        if (peek() == '}') {
            ++pos_;
            return object;
        }
        for (;;) {
            skip_whitespace();
            if (peek() != '"') {
                if (peek() == '}') fail_at(pos_, "trailing comma before '}' is not allowed in JSON");
                fail_at(pos_, "expected a member name in double quotes, found " + describe(pos_));
            }
            const std::size_t key_offset = pos_;
            std::string key = parse_string();
            if (!keys.insert(key).second) fail_at(key_offset, "duplicate key '" + key + "'");
            skip_whitespace();
            if (peek() != ':')
                fail_at(pos_, "expected ':' after member name '" + key + "', found " + describe(pos_));
            ++pos_;
            Json member = parse_value(member_path(path, key), depth + 1);
            object.object_.emplace_back(std::move(key), std::move(member));
            skip_whitespace();
            if (peek() == ',') {
                ++pos_;
                continue;
            }
            if (peek() == '}') {
                ++pos_;
                return object;
            }
            fail_at(pos_, "expected ',' or '}' after member '" + object.object_.back().first +
                              "', found " + describe(pos_));
        }
    }

    Json parse_array(const std::string& path, int depth) {
        if (depth >= kMaxDepth) fail_at(pos_, "nesting deeper than " + std::to_string(kMaxDepth));
        ++pos_;  // '['
        Json array = Json::array();
        skip_whitespace();
        if (peek() == ']') {
            ++pos_;
            return array;
        }
        for (;;) {
            skip_whitespace();
            if (peek() == ']') fail_at(pos_, "trailing comma before ']' is not allowed in JSON");
            array.array_.push_back(
                parse_value(path + "[" + std::to_string(array.array_.size()) + "]", depth + 1));
            skip_whitespace();
            if (peek() == ',') {
                ++pos_;
                continue;
            }
            if (peek() == ']') {
                ++pos_;
                return array;
            }
            fail_at(pos_, "expected ',' or ']' in array, found " + describe(pos_));
        }
    }

    static bool is_digit(char c) { return c >= '0' && c <= '9'; }

    double parse_number() {
        const std::size_t start = pos_;
        if (peek() == '-') ++pos_;
        if (!is_digit(peek())) fail_at(pos_, "expected a digit after '-', found " + describe(pos_));
        if (peek() == '0' && pos_ + 1 < text_.size() && is_digit(text_[pos_ + 1]))
            fail_at(pos_, "leading zeros are not allowed in JSON numbers");
        while (is_digit(peek())) ++pos_;
        if (peek() == '.') {
            ++pos_;
            if (!is_digit(peek()))
                fail_at(pos_, "expected a digit after the decimal point, found " + describe(pos_));
            while (is_digit(peek())) ++pos_;
        }
        if (peek() == 'e' || peek() == 'E') {
            ++pos_;
            if (peek() == '+' || peek() == '-') ++pos_;
            if (!is_digit(peek()))
                fail_at(pos_, "expected a digit in the exponent, found " + describe(pos_));
            while (is_digit(peek())) ++pos_;
        }
        const std::string literal(text_.substr(start, pos_ - start));
        double value = 0;
        if (!read_double(literal, value)) fail_at(start, "number " + literal + " is out of range");
        return value;
    }

    unsigned read_hex4() {
        unsigned code = 0;
        for (int i = 0; i < 4; ++i) {
            const char c = peek();
            unsigned digit;
            if (c >= '0' && c <= '9') digit = unsigned(c - '0');
            else if (c >= 'a' && c <= 'f') digit = unsigned(c - 'a' + 10);
            else if (c >= 'A' && c <= 'F') digit = unsigned(c - 'A' + 10);
            else fail_at(pos_, "expected 4 hex digits after \\u, found " + describe(pos_));
            code = code * 16 + digit;
            ++pos_;
        }
        return code;
    }

    static void append_utf8(std::string& out, std::uint32_t code) {
        if (code < 0x80) {
            out += char(code);
        } else if (code < 0x800) {
            out += char(0xC0 | (code >> 6));
            out += char(0x80 | (code & 0x3F));
        } else if (code < 0x10000) {
            out += char(0xE0 | (code >> 12));
            out += char(0x80 | ((code >> 6) & 0x3F));
            out += char(0x80 | (code & 0x3F));
        } else {
            out += char(0xF0 | (code >> 18));
            out += char(0x80 | ((code >> 12) & 0x3F));
            out += char(0x80 | ((code >> 6) & 0x3F));
            out += char(0x80 | (code & 0x3F));
        }
    }

    // Bytes outside escapes are copied as they are; the text is assumed to be UTF-8.
    std::string parse_string() {
        const std::size_t open_quote = pos_++;
        std::string out;
        for (;;) {
            if (at_end()) fail_at(open_quote, "unterminated string");
            const char c = text_[pos_];
            if (c == '"') {
                ++pos_;
                return out;
            }
            if (c == '\n' || c == '\r') fail_at(open_quote, "unterminated string (line break before the closing quote)");
            if (static_cast<unsigned char>(c) < 0x20)
                fail_at(pos_, "unescaped control character " + describe(pos_) + " in string");
            if (c != '\\') {
                out += c;
                ++pos_;
                continue;
            }
            const std::size_t escape_offset = pos_++;
            if (at_end()) fail_at(open_quote, "unterminated string");
            const char kind = text_[pos_++];
            switch (kind) {
                case '"': out += '"'; break;
                case '\\': out += '\\'; break;
                case '/': out += '/'; break;
                case 'b': out += '\b'; break;
                case 'f': out += '\f'; break;
                case 'n': out += '\n'; break;
                case 'r': out += '\r'; break;
                case 't': out += '\t'; break;
                case 'u': append_utf8(out, parse_unicode_escape(escape_offset)); break;
                default:
                    fail_at(escape_offset, "invalid escape '\\" + std::string(1, kind) + "' in string");
            }
        }
    }

    // UTF-16 surrogate pairs: code = 0x10000 + ((high - 0xD800) << 10) + (low - 0xDC00) (RFC 8259 s. 7).
    std::uint32_t parse_unicode_escape(std::size_t escape_offset) {
        const unsigned unit = read_hex4();
        if (unit >= 0xDC00 && unit <= 0xDFFF)
            fail_at(escape_offset, "unpaired low surrogate in \\u escape");
        if (unit < 0xD800 || unit > 0xDBFF) return unit;
        if (text_.substr(pos_, 2) != "\\u")
            fail_at(escape_offset, "high surrogate \\u escape is not followed by a low surrogate");
        const std::size_t low_offset = pos_;
        pos_ += 2;
        const unsigned low = read_hex4();
        if (low < 0xDC00 || low > 0xDFFF)
            fail_at(low_offset, "expected a low surrogate \\uDC00-\\uDFFF after a high surrogate");
        return 0x10000 + ((unit - 0xD800) << 10) + (low - 0xDC00);
    }

    std::string_view text_;
    std::shared_ptr<const std::string> source_;
    std::size_t bom_size_ = 0;  // a UTF-8 byte order mark is skipped and not counted as columns
    std::size_t pos_ = 0;
    int line_ = 1;
    std::size_t line_start_ = 0;
};

Json parse_json(std::string_view text, const std::string& source_name) {
    return JsonParser(text, source_name).parse_document();
}

Json read_json_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        std::error_code ec;
        const bool exists = std::filesystem::exists(path, ec);
        throw Error("cannot read JSON file '" + path.string() + "': " +
                    (exists ? "cannot open it" : "no such file"));
    }
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw Error("cannot read JSON file '" + path.string() + "': read error");
    return parse_json(text, path.string());
}

// ---------------------------------------------------------------------------------------------
// Access

namespace {

const char* type_phrase(Json::Type type) {
    switch (type) {
        case Json::Type::Null: return "null";
        case Json::Type::Bool: return "a boolean";
        case Json::Type::Number: return "a number";
        case Json::Type::String: return "a string";
        case Json::Type::Array: return "an array";
        case Json::Type::Object: return "an object";
    }
    return "unknown";
}

std::string location_prefix(const Json& value) {
    if (value.source_name().empty()) return std::string();
    return value.source_name() + ":" + std::to_string(value.line()) + ":" +
           std::to_string(value.column()) + ": ";
}

std::string subject(const std::string& path) {
    return path.empty() ? std::string("the top-level value") : "'" + path + "'";
}

}  // namespace

const std::string& Json::source_name() const {
    static const std::string none;
    return source_ ? *source_ : none;
}

void Json::fail(const std::string& what) const { throw Error(location_prefix(*this) + what); }

void Json::fail_type(const char* wanted) const {
    fail(subject(path_) + " must be " + wanted + ", not " + type_phrase(type_));
}

std::string Json::child_path(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
}

// Members built in code carry no position or path of their own, so the error is phrased from
// the parent: its path plus the key, and the member's position when it has one.
const Json& Json::required_member(const std::string& key, const char* wanted) const {
    if (type_ != Type::Object) fail_type("an object");
    const Json* member = find(key);
    if (!member)
        fail(subject(child_path(key)) + " is missing" + (wanted ? std::string("; it must be ") + wanted : ""));
    return *member;
}

bool Json::as_bool() const {
    if (type_ != Type::Bool) fail_type("a boolean");
    return bool_;
}
double Json::as_number() const {
    if (type_ != Type::Number) fail_type("a number");
    return number_;
}
const std::string& Json::as_string() const {
    if (type_ != Type::String) fail_type("a string");
    return string_;
}
const Json::Array& Json::as_array() const {
    if (type_ != Type::Array) fail_type("an array");
    return array_;
}
Json::Array& Json::as_array() {
    if (type_ != Type::Array) fail_type("an array");
    return array_;
}
const Json::Object& Json::as_object() const {
    if (type_ != Type::Object) fail_type("an object");
    return object_;
}
Json::Object& Json::as_object() {
    if (type_ != Type::Object) fail_type("an object");
    return object_;
}

std::size_t Json::size() const {
    if (type_ == Type::Array) return array_.size();
    if (type_ == Type::Object) return object_.size();
    return 0;
}

const Json& Json::at(std::size_t index) const {
    if (type_ != Type::Array) fail_type("an array");
    if (index >= array_.size())
        fail(subject(path_) + " has " + std::to_string(array_.size()) + " elements; index " +
             std::to_string(index) + " is out of range");
    return array_[index];
}

const Json* Json::find(const std::string& key) const {
    if (type_ != Type::Object) return nullptr;
    for (const Member& member : object_)
        if (member.first == key) return &member.second;
    return nullptr;
}

Json& Json::operator[](const std::string& key) {
    if (type_ == Type::Null) type_ = Type::Object;
    if (type_ != Type::Object) fail_type("an object");
    for (Member& member : object_)
        if (member.first == key) return member.second;
    object_.emplace_back(key, Json());
    return object_.back().second;
}

void Json::push_back(Json value) {
    if (type_ == Type::Null) type_ = Type::Array;
    if (type_ != Type::Array) fail_type("an array");
    array_.push_back(std::move(value));
}

namespace {

[[noreturn]] void fail_member(const Json& parent, const Json& member, const std::string& path,
                              const std::string& what) {
    const Json& located = member.source_name().empty() ? parent : member;
    throw Error(location_prefix(located) + subject(path) + " " + what);
}

}  // namespace

const Json& Json::member_at(const std::string& key) const { return required_member(key, nullptr); }

double Json::number_at(const std::string& key) const {
    const Json& member = required_member(key, "a number");
    if (!member.is_number())
        fail_member(*this, member, child_path(key), std::string("must be a number, not ") + type_phrase(member.type()));
    return member.number_;
}

namespace {

bool fits_int(double value) {
    return std::floor(value) == value && value >= double(std::numeric_limits<int>::min()) &&
           value <= double(std::numeric_limits<int>::max());
}

std::string number_text(double value) { return Json(value).dump(); }

}  // namespace

int Json::int_at(const std::string& key) const {
    const Json& member = required_member(key, "an integer");
    if (!member.is_number())
        fail_member(*this, member, child_path(key), std::string("must be an integer, not ") + type_phrase(member.type()));
    if (!fits_int(member.number_))
        fail_member(*this, member, child_path(key), "must be an integer, not " + number_text(member.number_));
    return static_cast<int>(member.number_);
}

bool Json::bool_at(const std::string& key) const {
    const Json& member = required_member(key, "a boolean");
    if (!member.is_bool())
        fail_member(*this, member, child_path(key), std::string("must be a boolean, not ") + type_phrase(member.type()));
    return member.bool_;
}

std::string Json::string_at(const std::string& key) const {
    const Json& member = required_member(key, "a string");
    if (!member.is_string())
        fail_member(*this, member, child_path(key), std::string("must be a string, not ") + type_phrase(member.type()));
    return member.string_;
}

const Json& Json::array_at(const std::string& key) const {
    const Json& member = required_member(key, "an array");
    if (!member.is_array())
        fail_member(*this, member, child_path(key), std::string("must be an array, not ") + type_phrase(member.type()));
    return member;
}

const Json& Json::object_at(const std::string& key) const {
    const Json& member = required_member(key, "an object");
    if (!member.is_object())
        fail_member(*this, member, child_path(key), std::string("must be an object, not ") + type_phrase(member.type()));
    return member;
}

double Json::number_or(const std::string& key, double fallback) const {
    if (type_ != Type::Object) fail_type("an object");
    const Json* member = find(key);
    return member && !member->is_null() ? number_at(key) : fallback;
}

int Json::int_or(const std::string& key, int fallback) const {
    if (type_ != Type::Object) fail_type("an object");
    const Json* member = find(key);
    return member && !member->is_null() ? int_at(key) : fallback;
}

bool Json::bool_or(const std::string& key, bool fallback) const {
    if (type_ != Type::Object) fail_type("an object");
    const Json* member = find(key);
    return member && !member->is_null() ? bool_at(key) : fallback;
}

std::string Json::string_or(const std::string& key, const std::string& fallback) const {
    if (type_ != Type::Object) fail_type("an object");
    const Json* member = find(key);
    return member && !member->is_null() ? string_at(key) : fallback;
}

// Objects compare as sets of members: key order is kept for people reading the file, not meaning.
bool operator==(const Json& a, const Json& b) {
    if (a.type_ != b.type_) return false;
    switch (a.type_) {
        case Json::Type::Null: return true;
        case Json::Type::Bool: return a.bool_ == b.bool_;
        case Json::Type::Number: return a.number_ == b.number_;
        case Json::Type::String: return a.string_ == b.string_;
        case Json::Type::Array: return a.array_ == b.array_;
        case Json::Type::Object:
            if (a.object_.size() != b.object_.size()) return false;
            for (const Json::Member& member : a.object_) {
                const Json* other = b.find(member.first);
                if (!other || *other != member.second) return false;
            }
            return true;
    }
    return false;
}

// ---------------------------------------------------------------------------------------------
// Writing

namespace {

void append_number(std::string& out, double value) {
    if (!std::isfinite(value)) {
        out += "null";
        return;
    }
    // Below 2^53 every integral double is exact, so it prints as the integer a person wrote.
    constexpr double kExactIntegerLimit = 9007199254740992.0;
    if (std::floor(value) == value && std::fabs(value) < kExactIntegerLimit) {
        out += std::to_string(static_cast<long long>(value));
        return;
    }
    std::string text;
    for (int digits = 15; digits <= 17; ++digits) {  // 17 significant digits always round-trip
        text = double_text(value, digits);
        double back = 0;
        if (read_double(text, back) && back == value) break;
    }
    out += text;
}

void append_string(std::string& out, const std::string& text) {
    static const char* hex = "0123456789abcdef";
    out += '"';
    for (const char ch : text) {
        const unsigned char c = static_cast<unsigned char>(ch);
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\b': out += "\\b"; break;
            case '\f': out += "\\f"; break;
            case '\n': out += "\\n"; break;
            case '\r': out += "\\r"; break;
            case '\t': out += "\\t"; break;
            default:
                if (c < 0x20) {
                    out += "\\u00";
                    out += hex[c >> 4];
                    out += hex[c & 15];
                } else {
                    out += ch;
                }
        }
    }
    out += '"';
}

void append_newline_indent(std::string& out, int indent, int depth) {
    if (indent <= 0) return;
    out += '\n';
    out.append(static_cast<std::size_t>(indent) * depth, ' ');
}

}  // namespace

void Json::dump_to(std::string& out, int indent, int depth) const {
    switch (type_) {
        case Type::Null: out += "null"; return;
        case Type::Bool: out += bool_ ? "true" : "false"; return;
        case Type::Number: append_number(out, number_); return;
        case Type::String: append_string(out, string_); return;
        case Type::Array:
            if (array_.empty()) {
                out += "[]";
                return;
            }
            out += '[';
            for (std::size_t i = 0; i < array_.size(); ++i) {
                if (i > 0) out += ',';
                append_newline_indent(out, indent, depth + 1);
                array_[i].dump_to(out, indent, depth + 1);
            }
            append_newline_indent(out, indent, depth);
            out += ']';
            return;
        case Type::Object:
            if (object_.empty()) {
                out += "{}";
                return;
            }
            out += '{';
            for (std::size_t i = 0; i < object_.size(); ++i) {
                if (i > 0) out += ',';
                append_newline_indent(out, indent, depth + 1);
                append_string(out, object_[i].first);
                out += indent > 0 ? ": " : ":";
                object_[i].second.dump_to(out, indent, depth + 1);
            }
            append_newline_indent(out, indent, depth);
            out += '}';
            return;
    }
}

std::string Json::dump(int indent) const {
    std::string out;
    dump_to(out, indent, 0);
    return out;
}

}  // namespace gsv
