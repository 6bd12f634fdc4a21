#pragma once
// The element of a list whose `name` member is the one asked for: ports, arrays, processors.
#include <string>
#include <vector>

namespace gsv {

template <class T>
const T* find_named(const std::vector<T>& items, const std::string& name) {
    for (const T& item : items)
        if (item.name == name) return &item;
    return nullptr;
}

}  // namespace gsv
