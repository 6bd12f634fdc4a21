#include "grader/src/cases/draw.h"

#include "common/core/error.h"
#include "common/core/number_text.h"

#include <chrono>
#include <cstdio>
#include <optional>
#include <random>
#include <sstream>

namespace gsv {
namespace {

std::pair<double, double> bounds(const Json& pair, const std::string& what) {
    const auto& a = pair.as_array();
    if (a.size() != 2 || a[0].as_number() > a[1].as_number())
        throw Error(pair.source_name() + ": " + what + " needs [low, high] with low <= high");
    return {a[0].as_number(), a[1].as_number()};
}

}  // namespace

SeededDraw::SeededDraw(std::uint64_t seed, const std::string& stream) : state_(seed) {
    // FNV-1a of the stream name, folded into the seed.
    std::uint64_t hash = 14695981039346656037ull;
    for (unsigned char c : stream) hash = (hash ^ c) * 1099511628211ull;
    state_ ^= hash;
}

std::uint64_t SeededDraw::next() {
    // splitmix64 (Steele, Lea and Flood, 2014).
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

double SeededDraw::uniform(double lo, double hi) {
    const double unit = static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0);  // 53 bits
    return lo + (hi - lo) * unit;
}

long SeededDraw::integer(long lo, long hi) {
    const auto span = static_cast<std::uint64_t>(hi - lo) + 1;
    return lo + static_cast<long>(next() % span);
}

std::vector<std::string> draw_settings(const Json& spec, SeededDraw& draw, const std::vector<std::string>& fixed) {
    std::vector<std::string> settings;
    std::vector<std::pair<std::size_t, const Json*>> conditional;  // index in settings, its "when"
    for (const auto& [name, how] : spec.as_object()) {
        if (const Json* when = how.find("when")) conditional.push_back({settings.size(), when});
        std::string value;
        if (how.contains("range")) {
            const auto [lo, hi] = bounds(how.array_at("range"), name + ".range");
            value = format_number(draw.uniform(lo, hi), 4);
        } else if (how.contains("int")) {
            const auto [lo, hi] = bounds(how.array_at("int"), name + ".int");
            // "step": every step-th whole number from the low end (2 from an odd one: the odd numbers).
            const long step = how.contains("step") ? static_cast<long>(how.number_at("step")) : 1;
            if (step < 1 || step != how.number_or("step", 1))
                throw Error(how.source_name() + ": " + name + ".step needs a whole number >= 1");
            const long first = static_cast<long>(lo), steps = (static_cast<long>(hi) - first) / step;
            value = std::to_string(first + step * draw.integer(0, steps));
        } else if (how.contains("choice")) {
            const auto& choices = how.array_at("choice").as_array();
            if (choices.empty()) throw Error(how.source_name() + ": " + name + ".choice is empty");
            value = choices[static_cast<std::size_t>(draw.integer(0, static_cast<long>(choices.size()) - 1))].as_string();
        } else if (how.contains("vec3")) {
            const auto& axes = how.array_at("vec3").as_array();
            if (axes.size() != 3) throw Error(how.source_name() + ": " + name + ".vec3 needs three [low, high] pairs");
            for (int i = 0; i < 3; ++i) {
                const auto [lo, hi] = bounds(axes[static_cast<std::size_t>(i)], name + ".vec3");
                value += (i ? "," : "") + format_number(draw.uniform(lo, hi), 4);
            }
        } else {
            throw Error(how.source_name() + ": '" + name + "' needs one of range, int, choice, vec3");
        }
        settings.push_back(name + "=" + value);
    }
    if (conditional.empty()) return settings;
    auto value_of = [&](const std::string& param) -> std::optional<std::string> {
        std::optional<std::string> found;
        for (const std::vector<std::string>* list : std::initializer_list<const std::vector<std::string>*>{&fixed, &settings})
            for (const auto& s : *list)
                if (s.rfind(param + "=", 0) == 0) found = s.substr(param.size() + 1);
        return found;
    };
    std::vector<bool> keep(settings.size(), true);
    for (const auto& [index, when] : conditional) {
        const std::string text = when->as_string();
        const auto eq = text.find('=');
        const std::string param = text.substr(0, eq);
        const std::optional<std::string> value = eq == std::string::npos ? std::nullopt : value_of(param);
        if (!value)
            throw Error(when->source_name() + ":" + std::to_string(when->line()) + ": \"when\": \"" + text +
                        "\" needs PARAM=VALUE|VALUE with a parameter the case sets or draws");
        bool holds = false;
        std::stringstream values(text.substr(eq + 1));
        for (std::string v; std::getline(values, v, '|');) holds = holds || v == *value;
        keep[index] = holds;
    }
    std::vector<std::string> kept;
    for (std::size_t i = 0; i < settings.size(); ++i)
        if (keep[i]) kept.push_back(settings[i]);
    return kept;
}

std::uint64_t fresh_seed() {
    std::random_device entropy;
    const auto now = static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
    return ((static_cast<std::uint64_t>(entropy()) << 32) ^ entropy() ^ now) % 1000000000ull;
}

}  // namespace gsv
