#include "support/network/processor_network.h"

#include "common/core/error.h"

#include <algorithm>
#include <deque>
#include <map>
#include <system_error>

namespace gsv {
namespace {

void add_unique(std::vector<std::string>& names, const std::string& name) {
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
}

}  // namespace

bool RunReport::ok() const {
    return std::all_of(processors.begin(), processors.end(),
                       [](const ProcessorRun& r) { return r.state == RunState::Ran; });
}

const ProcessorRun& RunReport::at(const std::string& processor) const {
    for (const ProcessorRun& r : processors)
        if (r.processor == processor) return r;
    throw Error("the run report has no processor '" + processor + "'");
}

std::string RunReport::text() const {
    std::string out;
    for (const ProcessorRun& r : processors) {
        out += r.processor + ": ";
        if (r.state == RunState::Failed) out += "failed: " + r.error;
        else if (r.state == RunState::Skipped) out += r.error;
        else out += run_state_name(r.state);
        out += "\n";
    }
    return out;
}

std::string port_image_file_name(const std::string& processor, const std::string& port) {
    return processor + "." + port + ".png";
}

std::vector<std::string> Network::processor_names() const {
    std::vector<std::string> names;
    for (const auto& p : processors_) names.push_back(p->name());
    return names;
}

Processor* Network::find(const std::string& name) const {
    for (const auto& p : processors_)
        if (p->name() == name) return p.get();
    return nullptr;
}

Processor& Network::processor(const std::string& name) const {
    if (Processor* p = find(name)) return *p;
    throw Error("no processor named '" + name + "' (the network has: " + list_or_none(processor_names()) + ")");
}

Processor& Network::add(const std::string& name, std::unique_ptr<Processor> processor) {
    if (!processor) throw Error("processor '" + name + "' is null");
    if (!is_network_name(name))
        throw Error("processor name '" + name + "' may only use letters, digits, '_' and '-'");
    if (find(name)) throw Error("a processor named '" + name + "' is already in the network");
    processor->name_ = name;
    processors_.push_back(std::move(processor));
    return *processors_.back();
}

const Connection* Network::connection_into(const PortRef& input) const {
    for (const Connection& c : connections_)
        if (c.to.processor == input.processor && c.to.port == input.port) return &c;
    return nullptr;
}

// The processors on the shortest path of connections from `from` down to `to`, both included; empty when `to`
// is not downstream of `from`. Breadth first, neighbours in connection order, so the path named is always
// the same one.
std::vector<std::string> Network::path_between(const std::string& from, const std::string& to) const {
    std::map<std::string, std::string> reached_from{{from, ""}};
    std::deque<std::string> queue{from};
    while (!queue.empty() && !reached_from.count(to)) {
        const std::string at = queue.front();
        queue.pop_front();
        for (const Connection& c : connections_)
            if (c.from.processor == at && !reached_from.count(c.to.processor)) {
                reached_from[c.to.processor] = at;
                queue.push_back(c.to.processor);
            }
    }
    if (!reached_from.count(to)) return {};
    std::vector<std::string> path{to};
    while (path.back() != from) path.push_back(reached_from[path.back()]);
    std::reverse(path.begin(), path.end());
    return path;
}

void Network::connect(const std::string& from_text, const std::string& to_text) {
    const std::string what = "cannot connect " + from_text + " -> " + to_text + ": ";
    auto parse = [&](const std::string& text) {
        const std::size_t dot = text.find('.');
        if (dot == std::string::npos || text.find('.', dot + 1) != std::string::npos)
            throw Error(what + "'" + text + "' is not <processor>.<port>");
        return PortRef{text.substr(0, dot), text.substr(dot + 1)};
    };
    const PortRef from = parse(from_text), to = parse(to_text);
    auto owner = [&](const PortRef& ref) -> Processor& {
        if (Processor* p = find(ref.processor)) return *p;
        throw Error(what + "no processor named '" + ref.processor + "' (the network has: " +
                    list_or_none(processor_names()) + ")");
    };
    Processor& source = owner(from);
    Processor& target = owner(to);

    const Port* out = source.find_output(from.port);
    if (!out && source.find_input(from.port))
        throw Error(what + from.text() + " is an input; a connection runs from an output to an input");
    if (!out)
        throw Error(what + source.describe() + " has no output '" + from.port + "' (its outputs: " +
                    list_or_none(port_names(source.outputs())) + ")");
    const Port* in = target.find_input(to.port);
    if (!in && target.find_output(to.port))
        throw Error(what + to.text() + " is an output; a connection runs from an output to an input");
    if (!in)
        throw Error(what + target.describe() + " has no input '" + to.port + "' (its inputs: " +
                    list_or_none(port_names(target.inputs())) + ")");

    if (out->type != in->type)
        throw Error(what + from.text() + " is a " + port_type_name(out->type) + " output, " + to.text() + " a " +
                    port_type_name(in->type) + " input");
    if (const Connection* existing = connection_into(to))
        throw Error(what + to.text() + " is already connected to " + existing->from.text() +
                    " (an input takes one connection)");
    // A connection into a processor that already feeds the source would make each wait for the other.
    const std::vector<std::string> back = path_between(to.processor, from.processor);
    if (!back.empty()) {
        std::string cycle = from.processor;
        for (const std::string& p : back) cycle += " -> " + p;
        throw Error(what + "it would close the cycle " + cycle);
    }
    connections_.push_back(Connection{from, to});
}

std::vector<std::string> Network::unconnected_inputs() const {
    std::vector<std::string> missing;
    for (const auto& p : processors_)
        for (const Port& in : p->inputs())
            if (!in.optional && !connection_into({p->name(), in.name})) missing.push_back(p->name() + "." + in.name);
    return missing;
}

void Network::validate() const {
    const std::vector<std::string> missing = unconnected_inputs();
    if (missing.size() == 1) throw Error(missing[0] + " is not connected");
    if (missing.size() > 1) throw Error(join_names(missing) + " are not connected");
}

std::vector<Processor*> Network::execution_order() const {
    // Repeatedly take the first processor, in the order added, whose every upstream processor is placed.
    // Quadratic, and networks have a handful of processors; Kahn's algorithm with a queue would reorder ties.
    std::vector<Processor*> order;
    std::vector<bool> placed(processors_.size(), false);
    auto is_placed = [&](const std::string& name) {
        for (std::size_t i = 0; i < processors_.size(); ++i)
            if (processors_[i]->name() == name) return bool(placed[i]);
        return false;
    };
    while (order.size() < processors_.size()) {
        bool found = false;
        for (std::size_t i = 0; i < processors_.size() && !found; ++i) {
            if (placed[i]) continue;
            const bool ready = std::all_of(connections_.begin(), connections_.end(), [&](const Connection& c) {
                return c.to.processor != processors_[i]->name() || is_placed(c.from.processor);
            });
            if (ready) {
                placed[i] = true;
                order.push_back(processors_[i].get());
                found = true;
            }
        }
        // connect() refuses cycles, so this would be a bug here rather than a mistake in a network.
        if (!found) throw Error("processor network has a cycle although connect() refuses them");
    }
    return order;
}

RunReport Network::run() {
    validate();
    for (const auto& p : processors_) {
        p->state_ = RunState::Pending;
        p->error_.clear();
        for (Port& port : p->inputs_) port.data = PortData();
        for (Port& port : p->outputs_) port.data = PortData();
    }
    // The failed processors that stopped each skipped one: a skip two steps down names the failure, not the
    // processor in between that was itself skipped.
    std::map<std::string, std::vector<std::string>> stopped_by;
    RunReport report;
    for (Processor* p : execution_order()) {
        std::vector<std::string> failed_upstream;
        for (const Port& in : p->inputs_) {
            const Connection* c = connection_into({p->name(), in.name});
            if (!c) continue;
            const Processor& up = processor(c->from.processor);
            if (up.state_ == RunState::Failed) add_unique(failed_upstream, up.name());
            if (up.state_ == RunState::Skipped)
                for (const std::string& name : stopped_by[up.name()]) add_unique(failed_upstream, name);
        }
        if (!failed_upstream.empty()) {
            p->state_ = RunState::Skipped;
            p->error_ = "not run: " + join_names(failed_upstream) + " failed";
            stopped_by[p->name()] = failed_upstream;
        } else {
            for (Port& in : p->inputs_)
                if (const Connection* c = connection_into({p->name(), in.name}))
                    in.data = processor(c->from.processor).find_output(c->from.port)->data;
            try {
                p->process();
                for (const Connection& c : connections_)
                    if (c.from.processor == p->name() && p->find_output(c.from.port)->data.empty())
                        throw Error("process() did not set output '" + c.from.port + "', which " + c.to.text() +
                                    " needs");
                p->state_ = RunState::Ran;
            } catch (const UnsupportedError& e) {
                // A GL feature the machine lacks is no fault of the network: the lab exits with its own status.
                p->state_ = RunState::Failed;
                p->error_ = e.what();
                throw;
            } catch (const std::exception& e) {
                p->state_ = RunState::Failed;
                p->error_ = e.what();
            }
        }
        report.processors.push_back(ProcessorRun{p->name(), p->state_, p->error_});
    }
    return report;
}

std::vector<std::filesystem::path> Network::write_port_images(const std::filesystem::path& folder,
                                                              const PortImageWriter& write) const {
    std::vector<std::filesystem::path> files;
    for (const Processor* p : execution_order())
        for (const Port& out : p->outputs()) {
            if (out.type != PortType::Image || out.data.empty()) continue;
            if (files.empty() && !folder.empty()) {
                std::error_code error;
                std::filesystem::create_directories(folder, error);
                if (error) throw Error("cannot create folder '" + folder.string() + "': " + error.message());
            }
            files.push_back(folder / port_image_file_name(p->name(), out.name));
            write(*p, out, files.back());
        }
    return files;
}

}  // namespace gsv
