#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "catch.hpp"
#include "common/core/error.h"
#include "support/network/network_file.h"
#include "support/network/processor_network.h"
#include "support/network/processor_registry.h"
#include "test_support.h"

namespace {

using gsv::PortType;
using gsv::RunState;
using gsv::test::gsv_error_message;

// Processors that pass numbers: a source, a doubler, an adder with an optional input, a sink. Each fails
// with the text of its "fail" parameter when that is set, so a test can break any one of them.
class NumberProcessor : public gsv::Processor {
public:
    using Processor::Processor;

protected:
    void fail_if_told() const {
        if (!param_text("fail").empty()) throw gsv::Error(param_text("fail"));
    }
};

class NumberSource : public NumberProcessor {
public:
    explicit NumberSource(double value = 1) : NumberProcessor("NumberSource"), value_(value) {
        add_output("value", PortType::Volume);
        params().add_text("fail", "", "the error process() throws, when not empty");
    }
    void process() override {
        fail_if_told();
        set_output("value", std::make_shared<double>(value_));
    }

private:
    double value_;
};

class Doubler : public NumberProcessor {
public:
    Doubler() : NumberProcessor("Doubler") {
        add_input("in", PortType::Volume);
        add_output("out", PortType::Volume);
        params().add_text("fail", "", "the error process() throws, when not empty");
    }
    void process() override {
        fail_if_told();
        set_output("out", std::make_shared<double>(2 * *input<double>("in")));
    }
};

class Adder : public NumberProcessor {
public:
    Adder() : NumberProcessor("Adder") {
        add_input("a", PortType::Volume);
        add_optional_input("b", PortType::Volume);
        add_output("sum", PortType::Volume);
        params().add_text("fail", "", "the error process() throws, when not empty");
    }
    void process() override {
        fail_if_told();
        const std::shared_ptr<double> b = input<double>("b");
        set_output("sum", std::make_shared<double>(*input<double>("a") + (b ? *b : 0)));
    }
};

class Sink : public NumberProcessor {
public:
    Sink() : NumberProcessor("Sink") {
        add_input("in", PortType::Volume);
        params().add_text("fail", "", "the error process() throws, when not empty");
    }
    void process() override {
        fail_if_told();
        got = *input<double>("in");
    }
    double got = 0;
};

// Declares an output it never sets, or sets it to an int where readers want a double.
class Careless : public gsv::Processor {
public:
    explicit Careless(bool writes_int) : Processor("Careless"), writes_int_(writes_int) {
        add_output("out", PortType::Volume);
    }
    void process() override {
        if (writes_int_) set_output("out", std::make_shared<int>(3));
    }

private:
    bool writes_int_;
};

// Stand-ins for lab 06's processors: each output is text saying how it was made, so the canvas shows the
// whole data flow as one string.
class TextProcessor : public gsv::Processor {
public:
    using Processor::Processor;

protected:
    std::string in(const std::string& port) const { return *input<std::string>(port); }
    void out(const std::string& port, const std::string& text) {
        set_output(port, std::make_shared<std::string>(text));
    }
};

class VolumeSource : public TextProcessor {
public:
    VolumeSource() : TextProcessor("VolumeSource") {
        add_output("volume", PortType::Volume);
        params().add_text("file", "data/volumes/anatomical.nii", "the volume's file");
    }
    void process() override { out("volume", "volume(" + param_text("file") + ")"); }
};

class ProxySource : public TextProcessor {
public:
    ProxySource() : TextProcessor("ProxySource") {
        add_input("volume", PortType::Volume);
        add_output("geometry", PortType::Geometry);
    }
    void process() override { out("geometry", "cube(" + in("volume") + ")"); }
};

class EntryExitPoints : public TextProcessor {
public:
    EntryExitPoints() : TextProcessor("EntryExitPoints") {
        add_input("geometry", PortType::Geometry);
        add_output("entry", PortType::Image);
        add_output("exit", PortType::Image);
    }
    void process() override {
        out("entry", "front(" + in("geometry") + ")");
        out("exit", "back(" + in("geometry") + ")");
    }
};

class RayTraversal : public TextProcessor {
public:
    RayTraversal() : TextProcessor("RayTraversal") {
        add_input("volume", PortType::Volume);
        add_input("entry", PortType::Image);
        add_input("exit", PortType::Image);
        params().add_choice("compositing", "dvr", {"dvr", "mip", "iso"}, "the compositing");
        params().add_choice("gradient", "central", {"central", "forward", "none"}, "the gradient");
        params().add_choice("shading", "phong", {"phong", "none"}, "the shading");
        add_output("image", PortType::Image);
    }
    void process() override {
        // What a shader that does not compile looks like from the network's side.
        if (param_text("compositing") == "iso") throw gsv::Error("raycast.frag:12: 'uIsoValue' : undeclared identifier");
        out("image", param_text("compositing") + "(" + in("volume") + ", " + in("entry") + ", " + in("exit") + ")");
    }
};

class Canvas : public TextProcessor {
public:
    Canvas() : TextProcessor("Canvas") { add_input("image", PortType::Image); }
    void process() override { shown = in("image"); }
    std::string shown;
};

// Image in, image out: for cycles among processors of one port type.
class ImageFilter : public TextProcessor {
public:
    ImageFilter() : TextProcessor("ImageFilter") {
        add_input("image", PortType::Image);
        add_output("image", PortType::Image);
    }
    void process() override { out("image", "filter(" + in("image") + ")"); }
};

gsv::ProcessorRegistry lab_registry() {
    gsv::ProcessorRegistry registry;
    registry.add<VolumeSource>();
    registry.add<ProxySource>();
    registry.add<EntryExitPoints>();
    registry.add<RayTraversal>();
    registry.add<Canvas>();
    registry.add<ImageFilter>();
    return registry;
}

const char* const kLabNetwork =
    "# a DVR of the MRI head\n"
    "processor VolumeSource source file=data/volumes/anatomical.nii\n"
    "processor ProxySource proxy\n"
    "processor EntryExitPoints entry_exit\n"
    "processor RayTraversal raycaster compositing=dvr gradient=central shading=phong\n"
    "processor Canvas output\n"
    "\n"
    "connect source.volume -> proxy.volume\n"
    "connect proxy.geometry -> entry_exit.geometry\n"
    "connect source.volume -> raycaster.volume   # the same volume feeds both\n"
    "connect entry_exit.entry -> raycaster.entry\n"
    "connect entry_exit.exit -> raycaster.exit\n"
    "connect raycaster.image -> output.image\n";

std::vector<std::string> order_names(const gsv::Network& network) {
    std::vector<std::string> names;
    for (const gsv::Processor* p : network.execution_order()) names.push_back(p->name());
    return names;
}

std::string parse_error(const std::string& text) {
    return gsv_error_message([&] { gsv::parse_network(text, "net.txt", lab_registry()); });
}

}  // namespace

TEST_CASE("network: processors built in code run in dependency order and pass data along", "[unit][network]") {
    gsv::Network network;
    Sink& sink = network.add<Sink>("sink");
    network.add<Doubler>("twice");
    network.add<NumberSource>("source", 3.0);
    network.add<Doubler>("once");
    network.connect("source.value", "once.in");
    network.connect("once.out", "twice.in");
    network.connect("twice.out", "sink.in");

    CHECK(order_names(network) == std::vector<std::string>{"source", "once", "twice", "sink"});
    const gsv::RunReport report = network.run();
    CHECK(report.ok());
    CHECK(sink.got == 12);
    CHECK(report.text() == "source: ran\nonce: ran\ntwice: ran\nsink: ran\n");
    CHECK(network.processor("twice").state() == RunState::Ran);
    CHECK(network.processor("twice").error().empty());
    // An output feeds any number of inputs, and an optional input may stay open.
    gsv::Network fan;
    fan.add<NumberSource>("source", 5.0);
    fan.add<Adder>("both");
    fan.add<Adder>("alone");
    fan.add<Sink>("sink");
    fan.connect("source.value", "both.a");
    fan.connect("source.value", "both.b");
    fan.connect("source.value", "alone.a");
    fan.connect("both.sum", "sink.in");
    CHECK(fan.run().ok());
    CHECK(static_cast<Sink&>(fan.processor("sink")).got == 10);
}

TEST_CASE("network: execution order is stable with ties broken by the order added", "[unit][network]") {
    gsv::Network network;
    network.add<Sink>("first_sink");
    network.add<NumberSource>("x");
    network.add<NumberSource>("y");
    network.add<Sink>("second_sink");
    network.connect("y.value", "second_sink.in");
    network.connect("x.value", "first_sink.in");
    // The first processor added that is free to go, each time: x, then the sink it frees, then y.
    CHECK(order_names(network) == std::vector<std::string>{"x", "first_sink", "y", "second_sink"});
    CHECK(order_names(network) == order_names(network));
    // Growing the network leaves the order of what was there alone.
    network.add<NumberSource>("z");
    CHECK(order_names(network) == std::vector<std::string>{"x", "first_sink", "y", "second_sink", "z"});
    // Connection order does not matter, only the order processors were added.
    gsv::Network same;
    same.add<Sink>("first_sink");
    same.add<NumberSource>("x");
    same.add<NumberSource>("y");
    same.add<Sink>("second_sink");
    same.connect("x.value", "first_sink.in");
    same.connect("y.value", "second_sink.in");
    CHECK(order_names(same) == std::vector<std::string>{"x", "first_sink", "y", "second_sink"});
}

TEST_CASE("network: connect names the unknown processor or port and the known ones", "[unit][network]") {
    gsv::Network network;
    network.add<NumberSource>("source");
    network.add<Doubler>("twice");
    CHECK(gsv_error_message([&] { network.connect("sorce.value", "twice.in"); }) ==
          "cannot connect sorce.value -> twice.in: no processor named 'sorce' (the network has: source, twice)");
    CHECK(gsv_error_message([&] { network.connect("source.value", "thrice.in"); }) ==
          "cannot connect source.value -> thrice.in: no processor named 'thrice' (the network has: source, twice)");
    CHECK(gsv_error_message([&] { network.connect("source.val", "twice.in"); }) ==
          "cannot connect source.val -> twice.in: source (NumberSource) has no output 'val' (its outputs: value)");
    CHECK(gsv_error_message([&] { network.connect("source.value", "twice.input"); }) ==
          "cannot connect source.value -> twice.input: twice (Doubler) has no input 'input' (its inputs: in)");
    CHECK(gsv_error_message([&] { network.connect("source", "twice.in"); }) ==
          "cannot connect source -> twice.in: 'source' is not <processor>.<port>");
    CHECK(gsv_error_message([&] { network.connect("source.value", "twice.in.x"); }) ==
          "cannot connect source.value -> twice.in.x: 'twice.in.x' is not <processor>.<port>");
    CHECK(network.connections().empty());
}

TEST_CASE("network: connect runs from an output to an input only", "[unit][network]") {
    gsv::Network network;
    network.add<NumberSource>("source");
    network.add<Doubler>("twice");
    network.add<Doubler>("again");
    CHECK(gsv_error_message([&] { network.connect("twice.in", "source.value"); }) ==
          "cannot connect twice.in -> source.value: twice.in is an input; a connection runs from an output to an "
          "input");
    CHECK(gsv_error_message([&] { network.connect("twice.out", "again.out"); }) ==
          "cannot connect twice.out -> again.out: again.out is an output; a connection runs from an output to an "
          "input");
}

TEST_CASE("network: connect refuses ports of different types naming both ports and types", "[unit][network]") {
    gsv::Network network;
    network.add("source", std::make_unique<VolumeSource>());
    network.add("points", std::make_unique<EntryExitPoints>());
    CHECK(gsv_error_message([&] { network.connect("source.volume", "points.geometry"); }) ==
          "cannot connect source.volume -> points.geometry: source.volume is a volume output, points.geometry a "
          "geometry input");
}

TEST_CASE("network: an input takes one connection", "[unit][network]") {
    gsv::Network network;
    network.add<NumberSource>("a");
    network.add<NumberSource>("b");
    network.add<Sink>("sink");
    network.connect("a.value", "sink.in");
    CHECK(gsv_error_message([&] { network.connect("b.value", "sink.in"); }) ==
          "cannot connect b.value -> sink.in: sink.in is already connected to a.value (an input takes one connection)");
    CHECK(gsv_error_message([&] { network.connect("a.value", "sink.in"); }) ==
          "cannot connect a.value -> sink.in: sink.in is already connected to a.value (an input takes one connection)");
    CHECK(network.connections().size() == 1);
}

TEST_CASE("network: connect refuses a cycle and names it", "[unit][network]") {
    gsv::Network network;
    network.add<Doubler>("a");
    network.add<Doubler>("b");
    network.add<Adder>("c");
    network.add<Adder>("d");
    network.connect("a.out", "b.in");
    network.connect("b.out", "c.a");
    network.connect("c.sum", "d.a");
    CHECK(gsv_error_message([&] { network.connect("c.sum", "a.in"); }) ==
          "cannot connect c.sum -> a.in: it would close the cycle c -> a -> b -> c");
    CHECK(gsv_error_message([&] { network.connect("d.sum", "a.in"); }) ==
          "cannot connect d.sum -> a.in: it would close the cycle d -> a -> b -> c -> d");
    CHECK(gsv_error_message([&] { network.connect("c.sum", "c.b"); }) ==
          "cannot connect c.sum -> c.b: it would close the cycle c -> c");
    CHECK(network.connections().size() == 3);
    // A diamond is no cycle.
    network.connect("b.out", "d.b");
    CHECK(order_names(network) == std::vector<std::string>{"a", "b", "c", "d"});
}

TEST_CASE("network: validate names every unconnected required input and optional ones may stay open", "[unit][network]") {
    gsv::Network network;
    network.add<NumberSource>("source");
    network.add<Adder>("add");
    network.add<Sink>("sink");
    CHECK(network.unconnected_inputs() == std::vector<std::string>{"add.a", "sink.in"});
    CHECK(gsv_error_message([&] { network.validate(); }) == "add.a and sink.in are not connected");
    CHECK(gsv_error_message([&] { network.run(); }) == "add.a and sink.in are not connected");
    network.connect("source.value", "add.a");
    CHECK(gsv_error_message([&] { network.validate(); }) == "sink.in is not connected");
    network.connect("add.sum", "sink.in");
    network.validate();  // add.b is optional
    CHECK(network.run().ok());
    CHECK(static_cast<Sink&>(network.processor("sink")).got == 1);
}

TEST_CASE("network: a failing processor marks everything downstream not run while independent branches run",
          "[unit][network]") {
    gsv::Network network;
    network.add<NumberSource>("left", 1.0);
    network.add<Doubler>("left_twice");
    network.add<Sink>("left_sink");
    network.add<NumberSource>("right", 2.0);
    network.add<Doubler>("right_twice");
    network.add<Sink>("right_sink");
    network.connect("left.value", "left_twice.in");
    network.connect("left_twice.out", "left_sink.in");
    network.connect("right.value", "right_twice.in");
    network.connect("right_twice.out", "right_sink.in");
    network.processor("left_twice").set_param("fail", "double.frag:3: syntax error");

    const gsv::RunReport report = network.run();
    CHECK_FALSE(report.ok());
    CHECK(report.text() ==
          "left: ran\n"
          "left_twice: failed: double.frag:3: syntax error\n"
          "left_sink: not run: left_twice failed\n"
          "right: ran\n"
          "right_twice: ran\n"
          "right_sink: ran\n");
    CHECK(report.at("left_twice").state == RunState::Failed);
    CHECK(report.at("left_twice").error == "double.frag:3: syntax error");
    CHECK(report.at("left_sink").state == RunState::Skipped);
    CHECK(static_cast<Sink&>(network.processor("right_sink")).got == 4);
    // The state stays on the processor that owns it, for the window to show there.
    CHECK(network.processor("left_twice").state() == RunState::Failed);
    CHECK(network.processor("left_twice").error() == "double.frag:3: syntax error");
    CHECK(network.processor("left_sink").error() == "not run: left_twice failed");
    CHECK(gsv_error_message([&] { (void)report.at("nobody"); }) == "the run report has no processor 'nobody'");
}

TEST_CASE("network: a skip two steps down names the failures that caused it", "[unit][network]") {
    gsv::Network network;
    network.add<NumberSource>("a");
    network.add<NumberSource>("b");
    network.add<Adder>("add");
    network.add<Doubler>("twice");
    network.add<Sink>("sink");
    network.connect("a.value", "add.a");
    network.connect("b.value", "add.b");
    network.connect("add.sum", "twice.in");
    network.connect("twice.out", "sink.in");
    network.processor("a").set_param("fail", "cannot read a.nii");
    network.processor("b").set_param("fail", "cannot read b.nii");
    const gsv::RunReport report = network.run();
    CHECK(report.text() ==
          "a: failed: cannot read a.nii\n"
          "b: failed: cannot read b.nii\n"
          "add: not run: a and b failed\n"
          "twice: not run: a and b failed\n"
          "sink: not run: a and b failed\n");
}

TEST_CASE("network: a second run starts clean", "[unit][network]") {
    gsv::Network network;
    network.add<NumberSource>("source", 4.0);
    network.add<Sink>("sink");
    network.connect("source.value", "sink.in");
    network.processor("source").set_param("fail", "broken");
    CHECK(network.run().text() == "source: failed: broken\nsink: not run: source failed\n");
    CHECK(network.processor("source").outputs()[0].data.empty());

    network.processor("source").set_param("fail", "");
    CHECK(network.run().ok());
    CHECK(network.processor("source").error().empty());
    CHECK(network.processor("sink").state() == RunState::Ran);
    CHECK(network.processor("sink").error().empty());
    CHECK(static_cast<Sink&>(network.processor("sink")).got == 4);
    CHECK(*network.processor("source").outputs()[0].data.as<double>() == 4);
}

TEST_CASE("network: an empty connected output or a value of the wrong C++ type fails its processor", "[unit][network]") {
    gsv::Network network;
    network.add("lazy", std::make_unique<Careless>(false));
    network.add("unread", std::make_unique<Careless>(false));
    network.add("ints", std::make_unique<Careless>(true));
    network.add<Sink>("after_lazy");
    network.add<Sink>("after_ints");
    network.connect("lazy.out", "after_lazy.in");
    network.connect("ints.out", "after_ints.in");
    const gsv::RunReport report = network.run();
    CHECK(report.text() ==
          "lazy: failed: process() did not set output 'out', which after_lazy.in needs\n"
          "unread: ran\n"
          "ints: ran\n"
          "after_lazy: not run: lazy failed\n"
          "after_ints: failed: input after_ints.in holds another C++ type than process() asks for\n");
}

TEST_CASE("network: any exception from process is reported but a missing GL feature ends the run", "[unit][network]") {
    class Throws : public gsv::Processor {
    public:
        explicit Throws(bool unsupported) : Processor("Throws"), unsupported_(unsupported) {}
        void process() override {
            if (unsupported_) throw gsv::UnsupportedError("compute shaders need OpenGL 4.3");
            throw std::out_of_range("vector::_M_range_check");
        }

    private:
        bool unsupported_;
    };
    gsv::Network network;
    network.add("buggy", std::make_unique<Throws>(false));
    CHECK(network.run().text() == "buggy: failed: vector::_M_range_check\n");
    network.add("old_gl", std::make_unique<Throws>(true));
    CHECK_THROWS_AS(network.run(), gsv::UnsupportedError);
    CHECK(network.processor("old_gl").error() == "compute shaders need OpenGL 4.3");
}

TEST_CASE("network: parameters are declared with defaults and choices and unknown ones list the known", "[unit][network]") {
    RayTraversal raycaster;
    CHECK(raycaster.param_text("compositing") == "dvr");
    CHECK_FALSE(raycaster.is_set("compositing"));
    CHECK(gsv_error_message([&] { raycaster.set_param("shadng", "none"); }) ==
          "RayTraversal has no parameter 'shadng' (its parameters: compositing, gradient, shading)");
    gsv::Network network;
    gsv::Processor& named = network.add("raycaster", std::make_unique<RayTraversal>());
    named.set_param("compositing", "mip");
    CHECK(named.param_text("compositing") == "mip");
    CHECK(named.is_set("compositing"));
    CHECK_FALSE(named.is_set("shading"));
    // The one parser of every parameter (Params::set): the same words as on the command line.
    CHECK(gsv_error_message([&] { named.set_param("compositing", "dvx"); }) ==
          "parameter 'compositing' = 'dvx' is not one of: dvr, mip, iso");
    CHECK(gsv_error_message([&] { (void)named.param_text("shadng"); }) ==
          "raycaster (RayTraversal) has no parameter 'shadng' (its parameters: compositing, gradient, shading)");

    class Sloppy : public gsv::Processor {
    public:
        explicit Sloppy(int mistake) : Processor("Sloppy") {
            params().add_choice("mode", "a", {"a", "b"}, "a mode");
            add_input("in", PortType::Image);
            add_output("out", PortType::Image);
            if (mistake == 0) params().add_choice("mode", "b", {"a", "b"}, "a mode");
            if (mistake == 1) params().add_choice("level", "high", {"low", "mid"}, "a level");
            if (mistake == 2) add_optional_input("in", PortType::Volume);
            if (mistake == 3) add_output("out", PortType::Volume);
            if (mistake == 4) add_output("out.png", PortType::Image);
            if (mistake == 5) params().add_text("a=b", "", "a name no file can hold");
        }
        void process() override {}
    };
    CHECK(gsv_error_message([] { Sloppy(0); }) == "parameter 'mode' declared twice");
    CHECK(gsv_error_message([] { Sloppy(1); }) ==
          "parameter 'level' defaults to 'high', which is not one of its choices");
    CHECK(gsv_error_message([] { Sloppy(2); }) == "Sloppy: input 'in' declared twice");
    CHECK(gsv_error_message([] { Sloppy(3); }) == "Sloppy: output 'out' declared twice");
    CHECK(gsv_error_message([] { Sloppy(4); }) ==
          "Sloppy: output name 'out.png' may only use letters, digits, '_' and '-'");
    CHECK(gsv_error_message([] { Sloppy(5); }) ==
          "parameter name 'a=b' may only use letters, digits, '_' and '-'");
}

TEST_CASE("network: processor names are unique and file-safe and unknown ones list the known", "[unit][network]") {
    gsv::Network network;
    network.add<NumberSource>("source");
    CHECK(gsv_error_message([&] { network.add<Sink>("source"); }) ==
          "a processor named 'source' is already in the network");
    CHECK(gsv_error_message([&] { network.add<Sink>("my sink"); }) ==
          "processor name 'my sink' may only use letters, digits, '_' and '-'");
    CHECK(gsv_error_message([&] { network.add<Sink>(""); }) ==
          "processor name '' may only use letters, digits, '_' and '-'");
    CHECK(gsv_error_message([&] { network.add<Sink>("sink.png"); }) ==
          "processor name 'sink.png' may only use letters, digits, '_' and '-'");
    CHECK(gsv_error_message([&] { network.processor("sorce"); }) ==
          "no processor named 'sorce' (the network has: source)");
    CHECK(network.find("sorce") == nullptr);
    CHECK(network.find("source") == &network.processor("source"));
    CHECK(network.processors().size() == 1);
}

TEST_CASE("network: the registry creates known types and lists them for an unknown one", "[unit][network]") {
    const gsv::ProcessorRegistry registry = lab_registry();
    CHECK(registry.create("RayTraversal")->type_name() == "RayTraversal");
    CHECK(registry.contains("Canvas"));
    CHECK_FALSE(registry.contains("canvas"));
    CHECK(registry.type_names() ==
          std::vector<std::string>{"VolumeSource", "ProxySource", "EntryExitPoints", "RayTraversal", "Canvas",
                                   "ImageFilter"});
    CHECK(gsv_error_message([&] { registry.create("RayTravesal"); }) ==
          "unknown processor type 'RayTravesal' (known: VolumeSource, ProxySource, EntryExitPoints, RayTraversal, "
          "Canvas, ImageFilter)");

    gsv::ProcessorRegistry mine;
    CHECK(gsv_error_message([&] { mine.create("Canvas"); }) == "unknown processor type 'Canvas' (known: none)");
    mine.add<Canvas>();
    CHECK(gsv_error_message([&] { mine.add<Canvas>(); }) == "processor type 'Canvas' registered twice");
    mine.add("Screen", [] { return std::make_unique<Canvas>(); });
    CHECK(gsv_error_message([&] { mine.create("Screen"); }) ==
          "the factory for processor type 'Screen' made a 'Canvas'");
}

TEST_CASE("network file: the lab network parses and runs from source to canvas", "[unit][network]") {
    gsv::Network network = gsv::parse_network(kLabNetwork, "dvr.txt", lab_registry());
    CHECK(order_names(network) == std::vector<std::string>{"source", "proxy", "entry_exit", "raycaster", "output"});
    CHECK(network.processor("raycaster").param_text("shading") == "phong");
    CHECK(network.connections().size() == 6);
    CHECK(network.run().ok());
    CHECK(static_cast<Canvas&>(network.processor("output")).shown ==
          "dvr(volume(data/volumes/anatomical.nii), front(cube(volume(data/volumes/anatomical.nii))), "
          "back(cube(volume(data/volumes/anatomical.nii))))");

    // A shader that fails on the raycaster shows there; the canvas says why it has nothing.
    network.processor("raycaster").set_param("compositing", "iso");
    const gsv::RunReport report = network.run();
    CHECK(report.text() ==
          "source: ran\n"
          "proxy: ran\n"
          "entry_exit: ran\n"
          "raycaster: failed: raycast.frag:12: 'uIsoValue' : undeclared identifier\n"
          "output: not run: raycaster failed\n");
}

TEST_CASE("network file: blanks and quotes and comments and CRLF line ends", "[unit][network]") {
    const std::string text =
        "\xEF\xBB\xBFprocessor Canvas output\r\n"
        "# exported on Windows, where paths have spaces\r\n"
        "   processor\tVolumeSource   source  file=\"my data/head #1.nii\"   # a comment\r\n"
        "\r\n"
        "processor ProxySource proxy\n"
        "processor EntryExitPoints points\n"
        "processor ImageFilter filter\n"
        "connect source.volume -> proxy.volume\n"
        "connect proxy.geometry -> points.geometry\n"
        "connect points.entry -> filter.image\n"
        "connect filter.image -> output.image\n";
    gsv::Network network = gsv::parse_network(text, "win.txt", lab_registry());
    CHECK(network.processor("source").param_text("file") == "my data/head #1.nii");
    CHECK(network.run().ok());
    CHECK(static_cast<Canvas&>(network.processor("output")).shown ==
          "filter(front(cube(volume(my data/head #1.nii))))");
}

TEST_CASE("network file: every mistake is one line naming the file and line", "[unit][network]") {
    const std::string three =
        "processor VolumeSource source\n"
        "processor ProxySource proxy\n"
        "processor EntryExitPoints entry_exit\n";
    struct Case {
        std::string text;
        std::string message;
    };
    const std::vector<Case> cases = {
        {"processor VolumeSource source\n\nprocesor Canvas output\n",
         "net.txt:3: unknown keyword 'procesor' (expected processor or connect)"},
        {"Processor Canvas output\n", "net.txt:1: unknown keyword 'Processor' (expected processor or connect)"},
        {"processor\n", "net.txt:1: processor needs a type and a name: processor <Type> <name> [key=value ...]"},
        {"processor shading=phong\n",
         "net.txt:1: processor needs a type and a name: processor <Type> <name> [key=value ...]"},
        {"processor RayTraversal\n",
         "net.txt:1: processor RayTraversal needs an instance name: processor <Type> <name> [key=value ...]"},
        {"processor RayTraversal compositing=mip\n",
         "net.txt:1: processor RayTraversal needs an instance name: processor <Type> <name> [key=value ...]"},
        {"processor RayTraversal raycaster compositing\n", "net.txt:1: 'compositing' is not key=value"},
        {"processor RayTraversal raycaster =mip\n", "net.txt:1: '=mip' is not key=value"},
        {"processor RayTravesal raycaster\n",
         "net.txt:1: unknown processor type 'RayTravesal' (known: VolumeSource, ProxySource, EntryExitPoints, "
         "RayTraversal, Canvas, ImageFilter)"},
        {"# shading\nprocessor RayTraversal raycaster shadng=phong\n",
         "net.txt:2: raycaster (RayTraversal) has no parameter 'shadng' (its parameters: compositing, gradient, "
         "shading)"},
        {"processor RayTraversal raycaster compositing=dvx\n",
         "net.txt:1: parameter 'compositing' = 'dvx' is not one of: dvr, mip, iso"},
        {"processor RayTraversal raycaster compositing=dvr compositing=mip\n",
         "net.txt:1: parameter 'compositing' is set twice for raycaster"},
        {"processor VolumeSource source\n\nprocessor Canvas source\n",
         "net.txt:3: processor name 'source' is already used on line 1"},
        {"processor Canvas out.put\n", "net.txt:1: processor name 'out.put' may only use letters, digits, '_' and '-'"},
        {"processor VolumeSource source file=\"my data/head.nii\n", "net.txt:1: a double quote is not closed"},
        {"processor VolumeSource source\nconnect source.volume -> proxy.volume\n",
         "net.txt:2: cannot connect source.volume -> proxy.volume: no processor named 'proxy' (the network has: "
         "source)"},
        {three + "connect source.vol -> proxy.volume\n",
         "net.txt:4: cannot connect source.vol -> proxy.volume: source (VolumeSource) has no output 'vol' (its "
         "outputs: volume)"},
        {three + "connect source.volume -> proxy.vol\n",
         "net.txt:4: cannot connect source.volume -> proxy.vol: proxy (ProxySource) has no input 'vol' (its "
         "inputs: volume)"},
        {three + "connect proxy.volume -> source.volume\n",
         "net.txt:4: cannot connect proxy.volume -> source.volume: proxy.volume is an input; a connection runs from "
         "an output to an input"},
        {three + "connect source.volume -> proxy.geometry\n",
         "net.txt:4: cannot connect source.volume -> proxy.geometry: proxy.geometry is an output; a connection runs "
         "from an output to an input"},
        {three + "connect source -> proxy.volume\n",
         "net.txt:4: cannot connect source -> proxy.volume: 'source' is not <processor>.<port>"},
        {three + "connect source.volume proxy.volume\n",
         "net.txt:4: expected connect <processor>.<output> -> <processor>.<input>"},
        {three + "connect source.volume -> proxy.volume extra\n",
         "net.txt:4: expected connect <processor>.<output> -> <processor>.<input>"},
        {three + "connect source.volume -> entry_exit.geometry\n",
         "net.txt:4: cannot connect source.volume -> entry_exit.geometry: source.volume is a volume output, "
         "entry_exit.geometry a geometry input"},
        {three + "connect source.volume -> proxy.volume\nconnect source.volume -> proxy.volume\n",
         "net.txt:5: cannot connect source.volume -> proxy.volume: proxy.volume is already connected to "
         "source.volume (an input takes one connection)"},
        {"processor ImageFilter a\nprocessor ImageFilter b\nprocessor ImageFilter c\n"
         "connect a.image -> b.image\nconnect b.image -> c.image\n# closes it\nconnect c.image -> a.image\n",
         "net.txt:7: cannot connect c.image -> a.image: it would close the cycle c -> a -> b -> c"},
        {"processor ImageFilter a\nconnect a.image -> a.image\n",
         "net.txt:2: cannot connect a.image -> a.image: it would close the cycle a -> a"},
    };
    for (const Case& c : cases) {
        INFO(c.text);
        CHECK(parse_error(c.text) == c.message);
    }
}

TEST_CASE("network file: required inputs left open are reported after the last line", "[unit][network]") {
    const std::string full = kLabNetwork;
    const std::string entry = "connect entry_exit.entry -> raycaster.entry\n";
    const std::string exit = "connect entry_exit.exit -> raycaster.exit\n";
    std::string no_entry = full;
    no_entry.erase(no_entry.find(entry), entry.size());
    CHECK(parse_error(no_entry) == "net.txt: raycaster.entry is not connected");
    std::string neither = no_entry;
    neither.erase(neither.find(exit), exit.size());
    CHECK(parse_error(neither) == "net.txt: raycaster.entry and raycaster.exit are not connected");
    CHECK(parse_error("processor Canvas a\nprocessor Canvas b\nprocessor Canvas c\n") ==
          "net.txt: a.image, b.image and c.image are not connected");
    // An empty file is an empty network, not an error.
    CHECK(gsv::parse_network("# nothing yet\n", "net.txt", lab_registry()).processors().empty());
}

TEST_CASE("network file: written text parses back to the same network", "[unit][network]") {
    // Canonical form: parameters that were set, in declared order; a blank line; connections in order made.
    const std::string canonical =
        "processor VolumeSource source file=\"my data/head.nii\"\n"
        "processor ProxySource proxy\n"
        "processor EntryExitPoints entry_exit\n"
        "processor RayTraversal raycaster compositing=dvr shading=none\n"
        "processor Canvas output\n"
        "\n"
        "connect source.volume -> proxy.volume\n"
        "connect proxy.geometry -> entry_exit.geometry\n"
        "connect source.volume -> raycaster.volume\n"
        "connect entry_exit.entry -> raycaster.entry\n"
        "connect entry_exit.exit -> raycaster.exit\n"
        "connect raycaster.image -> output.image\n";
    const gsv::ProcessorRegistry registry = lab_registry();
    gsv::Network parsed = gsv::parse_network(canonical, "canonical.txt", registry);
    CHECK(gsv::network_text(parsed) == canonical);

    // Properties written in another order, comments and blank lines: the same network, so the same text.
    const std::string messy =
        "# head\n"
        "processor VolumeSource source file=\"my data/head.nii\"\n"
        "processor ProxySource proxy\n\n"
        "processor EntryExitPoints entry_exit\n"
        "processor RayTraversal raycaster shading=none compositing=dvr  # dvr is the default, and stays\n"
        "processor Canvas output\n"
        "connect source.volume -> proxy.volume\n"
        "connect proxy.geometry -> entry_exit.geometry\n"
        "connect source.volume -> raycaster.volume\n"
        "connect entry_exit.entry -> raycaster.entry\n"
        "connect entry_exit.exit -> raycaster.exit\n"
        "connect raycaster.image -> output.image\n";
    CHECK(gsv::network_text(gsv::parse_network(messy, "messy.txt", registry)) == canonical);

    // A network built in code, through a file and back.
    gsv::Network built;
    built.add<VolumeSource>("source").set_param("file", "");
    built.add<ImageFilter>("unused");
    built.add<ProxySource>("proxy");
    built.connect("source.volume", "proxy.volume");
    const std::string text = gsv::network_text(built);
    CHECK(text ==
          "processor VolumeSource source file=\"\"\n"
          "processor ImageFilter unused\n"
          "processor ProxySource proxy\n"
          "\n"
          "connect source.volume -> proxy.volume\n");
    gsv::test::TempDir dir;
    gsv::write_network_file(dir.path("built.txt"), built);
    CHECK(gsv::test::read_text(dir.path("built.txt")) == text);
    // ImageFilter's input is open, which a file may not leave: the file names the file.
    CHECK(gsv_error_message([&] { gsv::read_network_file(dir.path("built.txt"), registry); }) ==
          dir.path("built.txt").string() + ": unused.image is not connected");

    gsv::Network unwritable;
    unwritable.add<VolumeSource>("source").set_param("file", "say \"hi\".nii");
    CHECK(gsv_error_message([&] { gsv::network_text(unwritable); }) ==
          "source.file = 'say \"hi\".nii' cannot be written to a network file (no double quotes or line breaks)");
}

TEST_CASE("network file: read_network_file names the file it cannot read and the line at fault", "[unit][network]") {
    gsv::test::TempDir dir;
    const gsv::ProcessorRegistry registry = lab_registry();
    CHECK(gsv_error_message([&] { gsv::read_network_file(dir.path("missing.txt"), registry); }) ==
          "cannot read network file '" + dir.path("missing.txt").string() + "': no such file");
    CHECK(gsv_error_message([&] { gsv::read_network_file(dir.path(), registry); }) ==
          "cannot read network file '" + dir.path().string() + "': cannot open it");
    const auto file = dir.write("network.txt", "processor Canvas output\nprocessor Canvas output\n");
    CHECK(gsv_error_message([&] { gsv::read_network_file(file, registry); }) ==
          file.string() + ":2: processor name 'output' is already used on line 1");
    dir.write("dvr.txt", kLabNetwork);
    CHECK(gsv::read_network_file(dir.path("dvr.txt"), registry).run().ok());
    CHECK(gsv_error_message([&] { gsv::write_network_file(dir.path("no/such/folder/x.txt"), gsv::Network()); }) ==
          "cannot write network file '" + dir.path("no/such/folder/x.txt").string() + "'");
}

TEST_CASE("network: port images are named processor.port.png and written for image outputs that hold data",
          "[unit][network]") {
    CHECK(gsv::port_image_file_name("raycaster", "image") == "raycaster.image.png");
    CHECK(gsv::port_image_file_name("entry_exit", "entry") == "entry_exit.entry.png");

    gsv::Network network = gsv::parse_network(kLabNetwork, "dvr.txt", lab_registry());
    gsv::test::TempDir dir;
    std::vector<std::string> written;
    const gsv::PortImageWriter write = [&](const gsv::Processor& processor, const gsv::Port& port,
                                           const std::filesystem::path& file) {
        written.push_back(processor.name() + "." + port.name + " " + file.filename().string() + " " +
                          *port.data.as<std::string>());
    };
    // Nothing has run, so nothing holds an image.
    CHECK(network.write_port_images(dir.path("ports"), write).empty());
    CHECK_FALSE(std::filesystem::exists(dir.path("ports")));

    network.run();
    const std::vector<std::filesystem::path> files = network.write_port_images(dir.path("ports"), write);
    CHECK(files == std::vector<std::filesystem::path>{dir.path("ports") / "entry_exit.entry.png",
                                                      dir.path("ports") / "entry_exit.exit.png",
                                                      dir.path("ports") / "raycaster.image.png"});
    CHECK(std::filesystem::is_directory(dir.path("ports")));
    const std::string volume = "volume(data/volumes/anatomical.nii)";
    CHECK(written == std::vector<std::string>{
                         "entry_exit.entry entry_exit.entry.png front(cube(" + volume + "))",
                         "entry_exit.exit entry_exit.exit.png back(cube(" + volume + "))",
                         "raycaster.image raycaster.image.png dvr(" + volume + ", front(cube(" + volume +
                             ")), back(cube(" + volume + ")))",
                     });

    // A failed raycaster has no image to show, but the entry and exit points that fed it still do.
    network.processor("raycaster").set_param("compositing", "iso");
    network.run();
    written.clear();
    CHECK(network.write_port_images(dir.path("ports"), write).size() == 2);
    CHECK(written.size() == 2);
}

TEST_CASE("network: port data keeps its C++ type", "[unit][network]") {
    const gsv::PortData empty;
    CHECK(empty.empty());
    CHECK(empty.as<double>() == nullptr);
    const gsv::PortData number(std::make_shared<double>(2.5));
    CHECK_FALSE(number.empty());
    CHECK(number.holds<double>());
    CHECK_FALSE(number.holds<float>());
    CHECK(*number.as<double>() == 2.5);
    CHECK(number.as<float>() == nullptr);
    CHECK(gsv::PortData(std::shared_ptr<int>()).empty());
    CHECK(std::string(gsv::port_type_name(PortType::Volume)) == "volume");
    CHECK(std::string(gsv::port_type_name(PortType::Image)) == "image");
    CHECK(std::string(gsv::port_type_name(PortType::Geometry)) == "geometry");
    CHECK(std::string(gsv::run_state_name(RunState::Skipped)) == "skipped");
}
