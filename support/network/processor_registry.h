#pragma once
// The processor types a network file may name, each with a factory: lab 06 registers its processors once,
// and read_network_file (support/network/network_file.h) creates them by name.
#include "support/network/processor.h"

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace gsv {

class ProcessorRegistry {
public:
    using Factory = std::function<std::unique_ptr<Processor>()>;

    // Throws gsv::Error for a type name registered twice.
    void add(const std::string& type_name, Factory factory);
    // The usual case: P is default-constructible and passes its type name to Processor's constructor.
    // Creating one here learns that name, so it is written once, in P (and P's constructor must not touch GL).
    template <typename P>
    void add() {
        add(P().type_name(), [] { return std::make_unique<P>(); });
    }

    // Throws gsv::Error for an unknown type, listing the known ones, and for a factory whose processor gives
    // another type name than the one it is registered under (a network file could not be read back).
    std::unique_ptr<Processor> create(const std::string& type_name) const;

    bool contains(const std::string& type_name) const;
    std::vector<std::string> type_names() const;  // in the order registered

private:
    std::vector<std::pair<std::string, Factory>> factories_;
};

}  // namespace gsv
