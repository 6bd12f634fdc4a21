#include "support/network/processor.h"

#include "common/core/enum_names.h"
#include "common/core/error.h"
#include "common/core/find_named.h"

#include <algorithm>
#include <cctype>

namespace gsv {

const char* port_type_name(PortType type) {
    static constexpr EnumName<PortType> kNames[] = {
        {PortType::Volume, "volume"}, {PortType::Image, "image"}, {PortType::Geometry, "geometry"}};
    return name_of(kNames, type);
}

const char* run_state_name(RunState state) {
    switch (state) {
    case RunState::Pending: return "pending";
    case RunState::Ran: return "ran";
    case RunState::Failed: return "failed";
    case RunState::Skipped: return "skipped";
    }
    return "?";
}

std::vector<std::string> port_names(const std::vector<Port>& ports) {
    std::vector<std::string> names;
    for (const Port& p : ports) names.push_back(p.name);
    return names;
}

std::string list_or_none(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? "none" : out;
}

bool is_network_name(const std::string& name) {
    return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
    });
}

std::string join_names(const std::vector<std::string>& names) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i)
        out += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return out;
}

Processor::Processor(std::string type_name) : type_name_(std::move(type_name)) {
    if (!is_network_name(type_name_))
        throw Error("processor type name '" + type_name_ + "' may only use letters, digits, '_' and '-'");
}

std::string Processor::describe() const { return name_.empty() ? type_name_ : name_ + " (" + type_name_ + ")"; }

std::string Processor::qualified(const std::string& member) const {
    return (name_.empty() ? type_name_ : name_) + "." + member;
}

const Port* Processor::find_input(const std::string& port) const { return find_named(inputs_, port); }
const Port* Processor::find_output(const std::string& port) const { return find_named(outputs_, port); }

void Processor::add_input(const std::string& name, PortType type) {
    if (!is_network_name(name))
        throw Error(type_name_ + ": input name '" + name + "' may only use letters, digits, '_' and '-'");
    if (find_input(name)) throw Error(type_name_ + ": input '" + name + "' declared twice");
    inputs_.push_back(Port{name, type, false, {}});
}

void Processor::add_optional_input(const std::string& name, PortType type) {
    add_input(name, type);
    inputs_.back().optional = true;
}

void Processor::add_output(const std::string& name, PortType type) {
    if (!is_network_name(name))
        throw Error(type_name_ + ": output name '" + name + "' may only use letters, digits, '_' and '-'");
    if (find_output(name)) throw Error(type_name_ + ": output '" + name + "' declared twice");
    outputs_.push_back(Port{name, type, false, {}});
}

std::size_t Processor::param_index(const std::string& name) const {
    const std::vector<ParamSpec>& specs = params_.specs();
    for (std::size_t i = 0; i < specs.size(); ++i)
        if (specs[i].name == name) return i;
    std::vector<std::string> known;
    for (const ParamSpec& s : specs) known.push_back(s.name);
    throw Error(describe() + " has no parameter '" + name + "' (its parameters: " + list_or_none(known) + ")");
}

void Processor::set_param(const std::string& name, const std::string& value) {
    const std::size_t i = param_index(name);
    params_.set(name, value);
    set_.resize(params_.specs().size());
    set_[i] = true;
}

std::string Processor::param_text(const std::string& name) const { return params_.text_at(param_index(name)); }

bool Processor::is_set(const std::string& name) const {
    const std::size_t i = param_index(name);
    return i < set_.size() && set_[i];
}

const Port& Processor::input_port(const std::string& port) const {
    const Port* in = find_input(port);
    if (!in)
        throw Error(describe() + " has no input '" + port + "' (its inputs: " + list_or_none(port_names(inputs_)) +
                    ")");
    // The network runs a processor only with every required input filled, so this is a processor run by hand.
    if (in->data.empty() && !in->optional) throw Error("input " + qualified(port) + " holds nothing");
    return *in;
}

Port& Processor::output_port(const std::string& port) {
    for (Port& p : outputs_)
        if (p.name == port) return p;
    throw Error(describe() + " has no output '" + port + "' (its outputs: " + list_or_none(port_names(outputs_)) +
                ")");
}

void Processor::fail_input_type(const std::string& port) const {
    // typeid names are mangled, so the message says where to look rather than which types.
    throw Error("input " + qualified(port) + " holds another C++ type than process() asks for");
}

}  // namespace gsv
