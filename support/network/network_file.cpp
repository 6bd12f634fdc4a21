#include "support/network/network_file.h"

#include "common/core/error.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>
#include <vector>

namespace gsv {
namespace {

const char* const kProcessorUsage = "processor <Type> <name> [key=value ...]";
const char* const kConnectUsage = "connect <processor>.<output> -> <processor>.<input>";

bool is_blank(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

class NetworkParser {
public:
    NetworkParser(const std::string& source_name, const ProcessorRegistry& registry)
        : source_(source_name), registry_(registry) {}

    Network parse(std::string_view text) {
        std::istringstream in{std::string(text)};
        for (std::string line; std::getline(in, line);) {
            ++line_;
            // Some Windows editors start UTF-8 files with a byte-order mark, which would hide the first keyword.
            if (line_ == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
            parse_line(split(line));
        }
        try {
            network_.validate();
        } catch (const Error& e) {
            throw Error(source_ + ": " + e.what());
        }
        return std::move(network_);
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw Error(source_ + ":" + std::to_string(line_) + ": " + what);
    }

    // Words at blanks, with "..." holding blanks; a word that starts with '#' ends the line.
    std::vector<std::string> split(const std::string& line) const {
        std::vector<std::string> words;
        std::size_t i = 0;
        while (true) {
            while (i < line.size() && is_blank(line[i])) ++i;
            if (i == line.size() || line[i] == '#') return words;
            std::string word;
            bool quoted = false;
            for (; i < line.size() && (quoted || !is_blank(line[i])); ++i) {
                if (line[i] == '"') quoted = !quoted;
                else word += line[i];
            }
            if (quoted) fail("a double quote is not closed");
            words.push_back(word);
        }
    }

    void parse_line(const std::vector<std::string>& words) {
        if (words.empty()) return;
        if (words[0] == "processor") return parse_processor(words);
        if (words[0] == "connect") return parse_connect(words);
        fail("unknown keyword '" + words[0] + "' (expected processor or connect)");
    }

    void parse_processor(const std::vector<std::string>& words) {
        auto has_eq = [&](std::size_t i) { return words[i].find('=') != std::string::npos; };
        if (words.size() < 2 || has_eq(1)) fail(std::string("processor needs a type and a name: ") + kProcessorUsage);
        if (words.size() < 3 || has_eq(2))
            fail("processor " + words[1] + " needs an instance name: " + kProcessorUsage);
        const std::string& type = words[1];
        const std::string& name = words[2];
        if (const auto seen = declared_on_.find(name); seen != declared_on_.end())
            fail("processor name '" + name + "' is already used on line " + std::to_string(seen->second));
        Processor* processor = nullptr;
        try {
            processor = &network_.add(name, registry_.create(type));
        } catch (const Error& e) {
            fail(e.what());
        }
        declared_on_[name] = line_;
        std::vector<std::string> keys;
        for (std::size_t i = 3; i < words.size(); ++i) {
            const std::size_t eq = words[i].find('=');
            if (eq == std::string::npos || eq == 0) fail("'" + words[i] + "' is not key=value");
            const std::string key = words[i].substr(0, eq);
            if (std::find(keys.begin(), keys.end(), key) != keys.end())
                fail("parameter '" + key + "' is set twice for " + name);
            keys.push_back(key);
            try {
                processor->set_param(key, words[i].substr(eq + 1));
            } catch (const Error& e) {
                fail(e.what());
            }
        }
    }

    void parse_connect(const std::vector<std::string>& words) {
        if (words.size() != 4 || words[2] != "->") fail(std::string("expected ") + kConnectUsage);
        try {
            network_.connect(words[1], words[3]);
        } catch (const Error& e) {
            fail(e.what());
        }
    }

    std::string source_;
    const ProcessorRegistry& registry_;
    Network network_;
    int line_ = 0;
    std::map<std::string, int> declared_on_;  // instance name -> line, for a name used twice
};

std::string value_text(const Processor& processor, const std::string& name) {
    const std::string v = processor.param_text(name);
    if (v.find_first_of("\"\n\r") != std::string::npos)
        throw Error(processor.name() + "." + name + " = '" + v +
                    "' cannot be written to a network file (no double quotes or line breaks)");
    const bool needs_quotes = v.empty() || std::any_of(v.begin(), v.end(), is_blank);
    return needs_quotes ? "\"" + v + "\"" : v;
}

}  // namespace

Network parse_network(std::string_view text, const std::string& source_name, const ProcessorRegistry& registry) {
    return NetworkParser(source_name, registry).parse(text);
}

Network read_network_file(const std::filesystem::path& path, const ProcessorRegistry& registry) {
    std::error_code ignored;
    std::ifstream in;
    // A directory opens as a stream on Linux and would then read as an empty network.
    if (!std::filesystem::is_directory(path, ignored)) in.open(path, std::ios::binary);
    if (!in.is_open())
        throw Error("cannot read network file '" + path.string() + "': " +
                    (std::filesystem::exists(path, ignored) ? "cannot open it" : "no such file"));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw Error("cannot read network file '" + path.string() + "'");
    return parse_network(text.str(), path.string(), registry);
}

std::string network_text(const Network& network) {
    std::string out;
    for (const auto& p : network.processors()) {
        out += "processor " + p->type_name() + " " + p->name();
        for (const ParamSpec& spec : p->params().specs())
            if (p->is_set(spec.name)) out += " " + spec.name + "=" + value_text(*p, spec.name);
        out += "\n";
    }
    if (!network.connections().empty()) out += "\n";
    for (const Connection& c : network.connections()) out += "connect " + c.from.text() + " -> " + c.to.text() + "\n";
    return out;
}

void write_network_file(const std::filesystem::path& path, const Network& network) {
    const std::string text = network_text(network);
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw Error("cannot write network file '" + path.string() + "'");
}

}  // namespace gsv
