#include "grader/src/golden/golden_renderers.h"

#include "common/core/error.h"
#include "common/io/json.h"

#include <fstream>

namespace gsv {

std::map<std::string, std::string> read_golden_renderers(const std::filesystem::path& file) {
    std::map<std::string, std::string> renderers;
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) return renderers;
    const Json root = read_json_file(file);
    for (const auto& [lab, renderer] : root.object_at("labs").as_object()) {
        if (!renderer.is_string() || renderer.as_string().empty())
            throw Error(file.string() + ":" + std::to_string(renderer.line()) + ": labs." + lab +
                        " must be the GL_RENDERER string the lab's goldens were rendered on");
        renderers[lab] = renderer.as_string();
    }
    return renderers;
}

void write_golden_renderers(const std::filesystem::path& file, const std::map<std::string, std::string>& renderers) {
    Json root = Json::object();
    root["about"] = "GL_RENDERER of the machine each lab's golden images were rendered on; written by gsv-grade --update-goldens";
    Json labs = Json::object();
    for (const auto& [lab, renderer] : renderers) labs[lab] = renderer;
    root["labs"] = labs;
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << root.dump(2) << "\n";
    if (!out) throw Error("cannot write " + file.string());
}

std::string renderer_family(const std::string& renderer) {
    const auto paren = renderer.find(" (");
    return paren == std::string::npos || paren == 0 ? renderer : renderer.substr(0, paren);
}

}  // namespace gsv
