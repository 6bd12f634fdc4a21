#include "support/network/processor_registry.h"

#include "common/core/error.h"

namespace gsv {

void ProcessorRegistry::add(const std::string& type_name, Factory factory) {
    if (!is_network_name(type_name))
        throw Error("processor type name '" + type_name + "' may only use letters, digits, '_' and '-'");
    if (contains(type_name)) throw Error("processor type '" + type_name + "' registered twice");
    if (!factory) throw Error("processor type '" + type_name + "' registered without a factory");
    factories_.emplace_back(type_name, std::move(factory));
}

bool ProcessorRegistry::contains(const std::string& type_name) const {
    for (const auto& [name, factory] : factories_)
        if (name == type_name) return true;
    return false;
}

std::vector<std::string> ProcessorRegistry::type_names() const {
    std::vector<std::string> names;
    for (const auto& entry : factories_) names.push_back(entry.first);
    return names;
}

std::unique_ptr<Processor> ProcessorRegistry::create(const std::string& type_name) const {
    for (const auto& [name, factory] : factories_) {
        if (name != type_name) continue;
        std::unique_ptr<Processor> processor = factory();
        if (!processor) throw Error("the factory for processor type '" + type_name + "' made nothing");
        if (processor->type_name() != type_name)
            throw Error("the factory for processor type '" + type_name + "' made a '" + processor->type_name() + "'");
        return processor;
    }
    std::string known;
    for (const auto& entry : factories_) known += (known.empty() ? "" : ", ") + entry.first;
    throw Error("unknown processor type '" + type_name + "' (known: " + (known.empty() ? "none" : known) + ")");
}

}  // namespace gsv
