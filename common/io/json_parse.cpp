// Parsing: nlohmann-json reads the text and reports it through its SAX interface; JsonParser builds
// gsv::Json values from those events and gives each the position of its first byte.
//
// nlohmann 3.11 tells a SAX handler nothing about where a value is, so the text is fed to its lexer
// through an iterator that counts the bytes taken. When an event arrives the lexer has taken the
// event's token and, after a number, one byte more. Between two events the only tokens it can have
// read without an event are ':' and ',', so the value or key an event reports starts at the first
// byte after the previous event's bytes that is neither whitespace nor ':' nor ','.
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_set>
#include <utility>
#include <vector>

#include "common/core/error.h"
#include "common/io/json.h"

namespace gsv {
namespace {

// Hands nlohmann's lexer one byte at a time and counts the bytes it has taken.
class CountingIterator {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    CountingIterator(const char* at, std::size_t* taken) : at_(at), taken_(taken) {}
    reference operator*() const { return *at_; }
    CountingIterator& operator++() {
        ++at_;
        ++*taken_;
        return *this;
    }
    CountingIterator operator++(int) {
        CountingIterator before = *this;
        ++*this;
        return before;
    }
    bool operator==(const CountingIterator& other) const { return at_ == other.at_; }
    bool operator!=(const CountingIterator& other) const { return at_ != other.at_; }

private:
    const char* at_;
    std::size_t* taken_;
};

struct TextPosition {
    int line;
    int column;
};

// Byte offsets to 1-based line and byte column. Offsets asked for mostly grow, so counting newlines
// carries on from the last answer and a whole parse costs one pass over the text.
class LineCounter {
public:
    explicit LineCounter(std::string_view text) : text_(text) {}

    TextPosition at(std::size_t offset) {
        if (offset < counted_) counted_ = 0, line_ = 1, line_start_ = 0;
        for (; counted_ < offset && counted_ < text_.size(); ++counted_)
            if (text_[counted_] == '\n') ++line_, line_start_ = counted_ + 1;
        return {line_, static_cast<int>(offset - line_start_ + 1)};
    }

private:
    std::string_view text_;
    std::size_t counted_ = 0;
    int line_ = 1;
    std::size_t line_start_ = 0;
};

// nlohmann quotes the token it stopped in ("last read: '...'"), which may be a whole string of any
// length; the error stays one short line by keeping the token's first and last bytes.
std::string shorten_quoted_token(std::string message) {
    static constexpr std::size_t kKeep = 24;
    for (const char* marker : {"last read: '", "parsing '"}) {
        const std::size_t marker_at = message.find(marker);
        if (marker_at == std::string::npos) continue;
        const std::size_t begin = marker_at + std::char_traits<char>::length(marker);
        std::size_t end = message.rfind("'; expected ");
        if (end == std::string::npos || end < begin) end = message.size() - 1;
        if (end <= begin || end - begin <= 2 * kKeep + 3) continue;
        auto continuation = [&](std::size_t i) { return (static_cast<unsigned char>(message[i]) & 0xC0) == 0x80; };
        std::size_t head_end = begin + kKeep, tail_begin = end - kKeep;
        while (head_end > begin && continuation(head_end)) --head_end;  // whole UTF-8 sequences only
        while (tail_begin < end && continuation(tail_begin)) ++tail_begin;
        message.replace(head_end, tail_begin - head_end, "...");
    }
    return message;
}

// "[json.exception.parse_error.101] parse error at line 1, column 4: syntax error ..." becomes
// "syntax error ...": the kit names the place itself, as source:line:column.
std::string nlohmann_reason(const nlohmann::detail::exception& error) {
    std::string message = error.what();
    const std::size_t tag_end = message.find("] ");
    if (message.rfind("[json.exception.", 0) == 0 && tag_end != std::string::npos) message.erase(0, tag_end + 2);
    if (message.rfind("parse error", 0) == 0) {
        const std::size_t colon = message.find(": ");
        if (colon != std::string::npos) message.erase(0, colon + 2);
    }
    return shorten_quoted_token(std::move(message));
}

bool is_json_whitespace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

class JsonParser {
public:
    JsonParser(std::string_view text, const std::string& source_name)
        : text_(text), source_(std::make_shared<const std::string>(source_name)), lines_(text) {}

    Json parse() {
        // nlohmann's lexer takes a NUL byte for the end of the input and would accept "{}\0anything";
        // JSON allows none anywhere (in strings it must be written \u0000).
        const std::size_t nul = text_.find('\0');
        if (nul != std::string_view::npos) fail_at(nul, "NUL byte: JSON text cannot contain one (write \\u0000 in a string)");
        CountingIterator begin(text_.data(), &taken_), end(text_.data() + text_.size(), nullptr);
        nlohmann::json::sax_parse(begin, end, this);
        return std::move(root_);
    }

    // The SAX interface nlohmann::json::sax_parse calls.
    bool null() { return add_scalar(Json()); }
    bool boolean(bool value) { return add_scalar(Json(value)); }
    bool number_integer(std::int64_t value) { return add_scalar(Json(static_cast<double>(value))); }
    bool number_unsigned(std::uint64_t value) { return add_scalar(Json(static_cast<double>(value))); }
    bool number_float(double value, const std::string& /*text*/) { return add_scalar(Json(value)); }
    bool string(std::string& value) { return add_scalar(Json(std::move(value))); }
    bool binary(nlohmann::json::binary_t& /*bytes*/) { return false; }  // only in binary formats, never in JSON text
    bool start_object(std::size_t /*unknown*/) { return open(Json::object()); }
    bool start_array(std::size_t /*unknown*/) { return open(Json::array()); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }

    // Duplicate keys are refused: in a hand-written case file the second is almost always a copy-paste mistake.
    bool key(std::string& name) {
        const std::size_t key_start = next_token_start();
        Frame& object = open_.back();
        if (!object.keys.insert(name).second) fail_at(key_start, "duplicate key '" + name + "'");
        object.key = std::move(name);
        events_end_ = taken_;
        return true;
    }

    bool parse_error(std::size_t bytes_read, const std::string& /*token*/, const nlohmann::detail::exception& error) {
        // A number too large for a double is reported by nlohmann after it has read the whole number
        // and more; it is named at its first digit like every other value.
        constexpr int kNumberOverflow = 406;
        const std::size_t offset = error.id == kNumberOverflow ? next_token_start()
                                   : bytes_read > 0                 ? bytes_read - 1
                                                                    : 0;
        fail_at(offset, nlohmann_reason(error));
    }

private:
    // Deep enough for any real case file, shallow enough that the recursive gsv::Json destructor,
    // comparison and dump cannot overflow the stack on hostile input.
    static constexpr std::size_t kMaxDepth = 256;

    struct Frame {
        Json container;
        std::string key;                        // of the member whose value comes next
        std::unordered_set<std::string> keys;   // seen so far in this object
    };

    [[noreturn]] void fail_at(std::size_t offset, const std::string& what) {
        const TextPosition at = lines_.at(offset);
        throw Error(*source_ + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": " + what);
    }

    std::size_t next_token_start() const {
        std::size_t at = events_end_;
        while (at < text_.size() && (is_json_whitespace(text_[at]) || text_[at] == ':' || text_[at] == ','))
            ++at;
        return at;
    }

    // Gives a value its position and key path; called when the value's first token arrives.
    void place(Json& value) {
        const TextPosition at = lines_.at(next_token_start());
        value.source_ = source_;
        value.line_ = at.line;
        value.column_ = at.column;
        if (open_.empty()) return;
        const Json& parent = open_.back().container;
        if (parent.is_array())
            value.path_ = parent.path_ + "[" + std::to_string(parent.array_.size()) + "]";
        else
            value.path_ = parent.path_.empty() ? open_.back().key : parent.path_ + "." + open_.back().key;
    }

    void attach(Json value) {
        if (open_.empty()) {
            root_ = std::move(value);
            return;
        }
        Frame& parent = open_.back();
        if (parent.container.is_array())
            parent.container.array_.push_back(std::move(value));
        else
            parent.container.object_.emplace_back(std::move(parent.key), std::move(value));
    }

    bool add_scalar(Json value) {
        place(value);
        attach(std::move(value));
        events_end_ = taken_;
        return true;
    }

    bool open(Json container) {
        place(container);
        if (open_.size() >= kMaxDepth) fail_at(next_token_start(), "nesting deeper than " + std::to_string(kMaxDepth));
        open_.push_back(Frame{std::move(container), std::string(), {}});
        events_end_ = taken_;
        return true;
    }

    bool close() {
        Json finished = std::move(open_.back().container);
        open_.pop_back();
        attach(std::move(finished));
        events_end_ = taken_;
        return true;
    }

    std::string_view text_;
    std::shared_ptr<const std::string> source_;
    LineCounter lines_;
    std::size_t taken_ = 0;       // bytes nlohmann's lexer has read
    std::size_t events_end_ = 0;  // bytes it had read at the previous event
    std::vector<Frame> open_;     // objects and arrays begun and not yet ended, outermost first
    Json root_;
};

Json parse_json(std::string_view text, const std::string& source_name) {
    // A UTF-8 byte order mark is skipped here rather than by nlohmann so that columns do not count it.
    static constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
    if (text.substr(0, kUtf8Bom.size()) == kUtf8Bom) text.remove_prefix(kUtf8Bom.size());
    return JsonParser(text, source_name).parse();
}

Json read_json_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        std::error_code ec;
        const bool exists = std::filesystem::exists(path, ec);
        throw Error("cannot read JSON file '" + path.string() + "': " + (exists ? "cannot open it" : "no such file"));
    }
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw Error("cannot read JSON file '" + path.string() + "': read error");
    return parse_json(text, path.string());
}

}  // namespace gsv
