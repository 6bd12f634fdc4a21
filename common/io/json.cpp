// Access to gsv::Json values: typed accessors whose errors name the source, position and key path.
// Parsing is in json_parse.cpp, writing in json_dump.cpp.
#include <cmath>
#include <limits>
#include <string>

#include "common/core/error.h"
#include "common/io/json.h"

namespace gsv {

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

}  // namespace gsv
