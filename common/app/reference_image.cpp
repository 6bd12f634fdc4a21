#include "common/app/reference_image.h"

#include "common/app/subprocess.h"
#include "common/core/error.h"
#include "common/io/temporary_folder.h"

#include <fstream>
#include <system_error>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// The settings a golden image shows: the lab's defaults with the case applied.
Params case_settings(Session& s, const std::string& case_name) {
    Params params = s.defaults;
    for (const RenderCase& c : s.named_cases())
        if (c.name == case_name)
            for (const std::string& setting : c.settings) params.set_assignment(setting);
    return params;
}

std::vector<std::string> changed_names(const Params& current, const Params& baseline) {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < current.specs().size(); ++i)
        if (current.text_at(i) != baseline.text_at(i)) names.push_back(current.specs()[i].name);
    return names;
}

std::string joined(const std::vector<std::string>& items) {
    std::string out;
    for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
    return out;
}

std::string last_line(const fs::path& file) {
    std::ifstream in(file);
    std::string line, last;
    while (std::getline(in, line))
        if (!line.empty()) last = line;
    return last;
}


}  // namespace

std::string ReferenceSource::describe(const Session& session) const {
    if (kind == Kind::Solution) return path.filename().string() + ", rendered now";
    const fs::path root = session.assets ? session.assets->root() : fs::path();
    const fs::path shown = root.empty() ? path : path.lexically_relative(root);
    return "golden image " + (shown.empty() ? path : shown).generic_string();
}

ReferenceSource find_reference(Session& s) {
    const fs::path sibling = s.executable.parent_path() / (s.info.id + "_solution" + s.executable.extension().string());
    std::error_code ec;
    const bool has_sibling = !s.executable.empty() && fs::is_regular_file(sibling, ec);
    if (has_sibling && !fs::equivalent(sibling, s.executable, ec)) return {ReferenceSource::Kind::Solution, sibling, ""};

    const std::string why_no_solution =
        has_sibling ? "this binary is " + sibling.filename().string()
                    : "there is no " + sibling.filename().string() + " beside " + s.executable.string();
    const std::string& name = s.options.case_name;
    if (name.empty()) {
        std::vector<std::string> graded;
        for (const RenderCase& c : s.named_cases())
            if (!c.todo.empty()) graded.push_back(c.name);
        throw Error("no reference to compare with: " + why_no_solution + ", and a golden image needs --case NAME (" +
                    joined(graded) + ")");
    }
    const fs::path golden = s.find_assets().layout().golden_image(s.info.id, name);
    if (!fs::is_regular_file(golden, ec))
        throw Error("no reference for case '" + name + "': " + why_no_solution + ", and there is no golden image " +
                    golden.string() + " (graded cases have one, demos none)");
    const std::vector<std::string> changed = changed_names(s.params, case_settings(s, name));
    if (!changed.empty())
        throw Error("the golden image " + golden.string() + " shows case '" + name + "' as its case file sets it, not with " +
                    joined(changed) + " changed; " + why_no_solution + " to render those settings");
    return {ReferenceSource::Kind::Golden, golden, name};
}

std::vector<std::string> reference_render_arguments(Session& s, const fs::path& png, int width, int height) {
    std::vector<std::string> args{"render", "--size", std::to_string(width) + "x" + std::to_string(height),
                                  "--frames", "1", "--warmup", "0", "--out", png.string(),
                                  "--profile", profile_name(s.options.profile)};
    if (s.options.gl) args.insert(args.end(), {"--gl", s.options.gl->str()});
    // A headless run's reference draws on the run's own backend (a hidden window where EGL is not built in); window
    // mode's draws on its own headless default.
    if (s.options.mode != RunMode::Window) args.insert(args.end(), {"--backend", backend_name(s.headless_backend())});
    Params asked = s.defaults;
    if (!s.options.case_name.empty()) {
        args.insert(args.end(), {"--case", s.options.case_name});
        asked = case_settings(s, s.options.case_name);
    }
    for (const std::string& assignment : s.options.assignments) {
        args.insert(args.end(), {"--set", assignment});
        asked.set_assignment(assignment);
    }
    // A value changed in a window that has no effect now (the field it belongs to was switched away) would be refused.
    for (const std::string& name : changed_names(s.params, asked))
        if (s.params.applies(name)) args.insert(args.end(), {"--set", name + "=" + s.params.get_text(name)});
    return args;
}

Image reference_image(Session& s, const ReferenceSource& source, int width, int height) {
    if (source.kind == ReferenceSource::Kind::Golden) return read_png(source.path);
    const TemporaryFolder folder("gsv-reference-");
    const fs::path png = folder.path() / "reference.png", log = folder.path() / "reference.log";
    std::vector<std::string> argv{source.path.string()};
    const std::vector<std::string> args = reference_render_arguments(s, png, width, height);
    argv.insert(argv.end(), args.begin(), args.end());
    const ProgramExit exit = run_program(argv, log);
    if (!exit.ok()) {
        const std::string said = last_line(log);
        throw Error("the reference " + source.path.string() +
                    (exit.signal ? " was killed by signal " + std::to_string(exit.signal)
                                 : " failed with exit status " + std::to_string(exit.code)) +
                    (said.empty() ? "" : ": " + said));
    }
    return read_png(png);
}

}  // namespace gsv
