#pragma once
// Lab 06's data-flow network: processors (support/network/processor.h) wired output to input, run in dependency
// order. Voreen builds such networks in a visual editor; here they are built in code or read from a small
// text file (support/network/network_file.h). Every mistake in the wiring is refused where it is made, with one line
// naming the ports; a processor that fails at run time is reported and the rest of the network still runs.
#include "support/network/processor.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace gsv {

// One end of a connection: "raycaster.entry".
struct PortRef {
    std::string processor;
    std::string port;
    std::string text() const { return processor + "." + port; }
};

struct Connection {
    PortRef from;  // an output
    PortRef to;    // an input
};

// How one processor fared in a run.
struct ProcessorRun {
    std::string processor;  // instance name
    RunState state = RunState::Pending;
    std::string error;  // a failed processor's message; "not run: source failed" for a skipped one
};

struct RunReport {
    std::vector<ProcessorRun> processors;  // in execution order
    bool ok() const;                       // every processor ran
    const ProcessorRun& at(const std::string& processor) const;  // throws gsv::Error for an unknown name
    // One line per processor: "raycaster: ran", "raycaster: failed: <error>", "canvas: not run: raycaster failed".
    std::string text() const;
};

// "raycaster.image.png": where an image output goes when a network's port images are written out.
std::string port_image_file_name(const std::string& processor, const std::string& port);

// Called for each image to write; the GL lab reads its texture back and saves it as `file`.
using PortImageWriter =
    std::function<void(const Processor& processor, const Port& port, const std::filesystem::path& file)>;

class Network {
public:
    // Adds a processor under an instance name and returns it. Throws gsv::Error for a name that is taken or not
    // file-safe (letters, digits, '_' and '-'), since it ends up in file names.
    Processor& add(const std::string& name, std::unique_ptr<Processor> processor);
    template <typename P, typename... Args>
    P& add(const std::string& name, Args&&... args) {
        return static_cast<P&>(add(name, std::make_unique<P>(std::forward<Args>(args)...)));
    }

    // connect("source.volume", "proxy.volume"): from an output to an input of the same port type. Throws
    // gsv::Error "cannot connect A -> B: <why>" for an unknown processor or port (listing the known ones),
    // the wrong direction, different port types, an input that is already connected (an output may feed
    // any number of inputs), or a connection that would close a cycle (naming the cycle).
    void connect(const std::string& from, const std::string& to);

    // The required inputs with no connection, "raycaster.entry", in the order processors were added.
    std::vector<std::string> unconnected_inputs() const;
    // Throws gsv::Error "raycaster.entry is not connected" (or "a.x and b.y are not connected").
    void validate() const;

    // Dependency order: each processor after everything feeding it and, among those free to go next, the one
    // added first, so the order stays the same as the network grows and reads like the file.
    std::vector<Processor*> execution_order() const;

    // validate()s, then calls every processor's process() in execution order, each time after filling its
    // inputs from the outputs connected to them. Outputs are emptied first, so nothing is left from the last
    // run. A process() that throws (gsv::Error, or any std::exception from a bug) marks that processor
    // failed and everything downstream of it skipped; independent branches still run. The report and each
    // processor's state() and error() say how it went.
    RunReport run();

    // Visual debugging: calls `write` for every image output that holds data (after run(), in execution order,
    // outputs in declared order) with the file `folder / port_image_file_name(...)`, and returns those files.
    // The entry and exit points and the raycaster's result can so be looked at one by one.
    std::vector<std::filesystem::path> write_port_images(const std::filesystem::path& folder,
                                                         const PortImageWriter& write) const;

    // Throws gsv::Error naming the processors the network has.
    Processor& processor(const std::string& name) const;
    Processor* find(const std::string& name) const;  // nullptr when there is none of that name
    // In the order added, and connections in the order made: how a network file writes them back.
    const std::vector<std::unique_ptr<Processor>>& processors() const { return processors_; }
    const std::vector<Connection>& connections() const { return connections_; }

private:
    std::vector<std::string> processor_names() const;
    const Connection* connection_into(const PortRef& input) const;
    std::vector<std::string> path_between(const std::string& from, const std::string& to) const;

    std::vector<std::unique_ptr<Processor>> processors_;
    std::vector<Connection> connections_;
};

}  // namespace gsv
