#pragma once
// An enum's names as command lines, lab parameters and files spell them: one table per enum, so a name and its
// parse cannot drift apart, and an unknown name is one line naming it and the known ones.
//
//   constexpr gsv::EnumName<Integrator> kIntegratorNames[] = {{Integrator::Euler, "euler"}, ...};
//   name_of(kIntegratorNames, Integrator::Rk4)                 -> "rk4"
//   parse_enum(kIntegratorNames, "integrator", "rk5")          -> throws "unknown integrator 'rk5' (known: euler, midpoint, rk4)"
#include "common/core/error.h"

#include <cstddef>
#include <string>

namespace gsv {

template <class E>
struct EnumName {
    E value;
    const char* name;
};

template <class E, std::size_t N>
const char* name_of(const EnumName<E> (&table)[N], E value) {
    for (const auto& entry : table)
        if (entry.value == value) return entry.name;
    return "unknown";
}

template <class E, std::size_t N>
E parse_enum(const EnumName<E> (&table)[N], const std::string& what, const std::string& name) {
    std::string known;
    for (const auto& entry : table) {
        if (name == entry.name) return entry.value;
        known += (known.empty() ? "" : ", ") + std::string(entry.name);
    }
    throw Error("unknown " + what + " '" + name + "' (known: " + known + ")");
}

}  // namespace gsv
