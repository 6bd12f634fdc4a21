#pragma once
// A processor of lab 06's data-flow network, after Voreen (Meyer-Spradow et al., GRAPP 2010; IEEE CG&A 2009): one step
// of a visualization (read a volume, draw its proxy geometry, cast the rays) with typed input and output
// ports and its own typed parameters (common/params/params.h; Inviwo's properties are the model). A processor
// never sees the network: the network fills its inputs
// from the outputs they are connected to, calls process() in dependency order, and remembers how it went.
//
// Nothing here touches GL, so a network can be built, checked and run in a unit test; the lab's
// processors put their textures, framebuffers and meshes into the ports.
#include "common/params/params.h"

#include <memory>
#include <string>
#include <typeinfo>
#include <vector>

namespace gsv {

// What a port carries, for checking connections; the C++ type inside is the processors' business.
enum class PortType { Volume, Image, Geometry };

// "volume", "image", "geometry": how messages and the network file name the types.
const char* port_type_name(PortType type);

// What travels along a connection: a shared pointer to anything (a gsv::Texture, a Framebuffer, a GpuMesh, a
// number in a test). Shared, because an output may feed several inputs and GL objects cannot be copied. It
// remembers the C++ type it was made from, so reading it as another type gives nullptr instead of garbage.
class PortData {
public:
    PortData() = default;
    template <typename T>
    PortData(std::shared_ptr<T> value) : value_(std::move(value)), type_(value_ ? &typeid(T) : nullptr) {}

    bool empty() const { return value_ == nullptr; }
    template <typename T>
    bool holds() const { return type_ && *type_ == typeid(T); }
    // The value, or nullptr when empty or when it was made from another type (as dynamic_pointer_cast does).
    template <typename T>
    std::shared_ptr<T> as() const { return holds<T>() ? std::static_pointer_cast<T>(value_) : nullptr; }

private:
    std::shared_ptr<void> value_;
    const std::type_info* type_ = nullptr;
};

struct Port {
    std::string name;  // "volume", "entry": unique among the processor's inputs, and among its outputs
    PortType type = PortType::Image;
    bool optional = false;  // inputs only: the processor runs without it, and reads nullptr
    PortData data;          // filled by run(): an output by its processor, an input from its connection
};

// Where a processor stands after the network's last run.
enum class RunState {
    Pending,  // not run yet
    Ran,
    Failed,   // its process() threw; error() says why
    Skipped,  // an upstream processor failed, so its inputs are missing; error() names which
};

const char* run_state_name(RunState state);  // "pending", "ran", "failed", "skipped"

class Processor {
public:
    // type_name: what network files call the class ("RayTraversal"). The instance name ("raycaster") is
    // given when the processor joins a network. Constructors must not touch GL: the registry builds one to
    // learn the type name, with or without a context. Compile shaders in process().
    explicit Processor(std::string type_name);
    virtual ~Processor() = default;
    Processor(const Processor&) = delete;
    Processor& operator=(const Processor&) = delete;

    const std::string& type_name() const { return type_name_; }
    const std::string& name() const { return name_; }
    std::string describe() const;  // "raycaster (RayTraversal)", or "RayTraversal" before it has a name

    // Reads the inputs (input<T>), reads its parameters, sets the outputs (set_output). Throws gsv::Error when it
    // cannot: the network marks this processor failed with the message, skips what depends on it, and
    // goes on with the rest. A processor that leaves a connected output empty fails, too.
    virtual void process() = 0;

    const std::vector<Port>& inputs() const { return inputs_; }
    const std::vector<Port>& outputs() const { return outputs_; }
    const Port* find_input(const std::string& port) const;   // nullptr when there is none of that name
    const Port* find_output(const std::string& port) const;

    // Its parameters, declared in the subclass's constructor (params().add_float(...) gives the typed handle it
    // reads). A network file and set_param set them by name, each parsed and checked by Params::set.
    Params& params() { return params_; }
    const Params& params() const { return params_; }
    // Throws gsv::Error for an unknown parameter (listing the known ones) or a value its type or range refuses.
    void set_param(const std::string& name, const std::string& value);
    std::string param_text(const std::string& name) const;  // throws as set_param does for an unknown one
    // Set from code or a file, even to the default: written back to a network file, so a file that names a
    // setting keeps naming it when saved, and kept when the lab's parameters change.
    bool is_set(const std::string& name) const;

    // The last run: a failed processor's error, "not run: <upstream> failed" for a skipped one, else empty.
    // The GL lab shows it on the processor, as Voreen shows a shader's compile log on its owner.
    RunState state() const { return state_; }
    const std::string& error() const { return error_; }

protected:
    // Declarations, made in the subclass's constructor. Each throws gsv::Error for a name that is not
    // file-safe (letters, digits, '_' and '-') or declared twice.
    void add_input(const std::string& name, PortType type);
    void add_optional_input(const std::string& name, PortType type);
    void add_output(const std::string& name, PortType type);

    // What the input holds, as a T. nullptr for an optional input left unconnected. Throws gsv::Error naming
    // the port for an unknown input, a required input that holds nothing, or a value of another C++ type.
    template <typename T>
    std::shared_ptr<T> input(const std::string& port) const {
        const Port& in = input_port(port);
        if (in.data.empty()) return nullptr;  // input_port refused an empty required input
        if (!in.data.holds<T>()) fail_input_type(port);
        return in.data.as<T>();
    }
    // Throws gsv::Error naming the known outputs for an unknown one.
    template <typename T>
    void set_output(const std::string& port, std::shared_ptr<T> value) {
        output_port(port).data = PortData(std::move(value));
    }

private:
    friend class Network;  // names the processor, fills its inputs, records its state

    const Port& input_port(const std::string& port) const;
    Port& output_port(const std::string& port);
    [[noreturn]] void fail_input_type(const std::string& port) const;
    std::size_t param_index(const std::string& name) const;  // throws listing the known parameters
    std::string qualified(const std::string& member) const;    // "raycaster.entry"

    std::string type_name_;
    std::string name_;
    std::vector<Port> inputs_;
    std::vector<Port> outputs_;
    Params params_;
    std::vector<bool> set_;  // per parameter, as declared
    RunState state_ = RunState::Pending;
    std::string error_;
};

// Processor, port and parameter names end up in file names ("raycaster.image.png") and in network files,
// where '.', '=', '#' and blanks mean something: letters, digits, '_' and '-' only, and not empty.
bool is_network_name(const std::string& name);

// "a", "a and b", "a, b and c": lists in one-line messages.
std::string join_names(const std::vector<std::string>& names);
// "a, b, c", or "none": the known names an error lists beside an unknown one.
std::string list_or_none(const std::vector<std::string>& names);
std::vector<std::string> port_names(const std::vector<Port>& ports);

}  // namespace gsv
