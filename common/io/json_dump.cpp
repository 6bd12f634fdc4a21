// Writing: gsv::Json is converted to nlohmann::ordered_json, which keeps members in the order they
// were added, and nlohmann serialises it.
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "common/io/json.h"

namespace gsv {
namespace {

using OrderedJson = nlohmann::ordered_json;

OrderedJson number_value(double value) {
    // Below 2^53 every integral double is exact, so it is written as the integer a person wrote
    // (nlohmann would write 3.0 as "3.0"). Infinities and NaN stay doubles: nlohmann writes them as null.
    constexpr double kExactIntegerLimit = 9007199254740992.0;
    if (std::isfinite(value) && std::floor(value) == value && std::fabs(value) < kExactIntegerLimit)
        return OrderedJson(static_cast<std::int64_t>(value));
    return OrderedJson(value);
}

OrderedJson to_ordered_json(const Json& value) {
    switch (value.type()) {
        case Json::Type::Null: return OrderedJson(nullptr);
        case Json::Type::Bool: return OrderedJson(value.as_bool());
        case Json::Type::Number: return number_value(value.as_number());
        case Json::Type::String: return OrderedJson(value.as_string());
        case Json::Type::Array: {
            OrderedJson array = OrderedJson::array();
            for (const Json& element : value.as_array()) array.push_back(to_ordered_json(element));
            return array;
        }
        case Json::Type::Object: {
            OrderedJson object = OrderedJson::object();
            // Appended as they are: ordered_json's own insert would search the members for each key.
            auto& members = object.get_ref<OrderedJson::object_t&>();
            for (const Json::Member& member : value.as_object())
                members.emplace_back(member.first, to_ordered_json(member.second));
            return object;
        }
    }
    return OrderedJson(nullptr);
}

}  // namespace

std::string Json::dump(int indent) const {
    // nlohmann's indent 0 still breaks lines; -1 is one line. Bytes that are not UTF-8 (a student
    // program's output, say) become U+FFFD so that what is written can always be read back.
    return to_ordered_json(*this).dump(indent > 0 ? indent : -1, ' ', false, OrderedJson::error_handler_t::replace);
}

}  // namespace gsv
