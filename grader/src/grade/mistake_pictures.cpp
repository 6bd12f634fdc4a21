#include "grader/src/grade/mistake_pictures.h"

#include "common/core/error.h"
#include "common/io/folder_tree.h"
#include "grader/src/diagnose/mutant_kit.h"
#include "grader/src/run/lab_serve.h"
#include "tools/starter.h"

#include <cstdlib>
#include <fstream>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// Added to a key: the mistake did not render (a crash, NaN on this driver), which the store keeps as an entry of its own.
constexpr const char* kDidNotRender = "outcome: did not render\n";

}  // namespace

MistakePictures::~MistakePictures() {
    if (!dir_.empty()) remove_folder(dir_);
}

const MistakePictures::Kit& MistakePictures::kit_of(const KnownMistakes& known, const std::vector<std::size_t>& made) {
    std::string id = known.lab;
    for (const std::size_t m : made) id += "\n" + known.mistakes[m].name;
    if (const auto it = kits_.find(id); it != kits_.end()) return it->second;
    if (dir_.empty()) {
        std::string pattern = (fs::temp_directory_path() / "gsv-mistakes-XXXXXX").string();
        if (!mkdtemp(pattern.data())) throw Error("cannot make a folder for the known mistakes' kits in " + fs::temp_directory_path().string());
        dir_ = pattern;  // mkdtemp makes it 0700
    }
    const fs::path folder = dir_ / std::to_string(folders_++);  // a new one even after one that could not be made
    // A C++ mistake is made by the lab's _mistakes build, told which by its environment (cmake/labs.cmake); at most one
    // (a lab has one C++ TODO).
    std::string in_cpp;
    for (const std::size_t m : made)
        if (known.mistakes[m].cpp) {
            if (!in_cpp.empty()) throw Error("two C++ mistakes cannot be made together: '" + in_cpp + "' and '" + known.mistakes[m].name + "'");
            in_cpp = known.mistakes[m].switch_name;
        }
    const std::string binary = known.lab + (in_cpp.empty() ? "_solution" : "_mistakes");
    if (!fs::exists(s_.bin / binary)) throw Error("the known C++ mistakes' pictures need " + binary + ", which this build lacks");
    make_edited_kit(folder, s_.kit, s_.bin, known.lab, known.lab_dir, [&](const fs::path& lab_folder) {
        for (const std::size_t m : made) {
            const KnownMistake& mistake = known.mistakes[m];
            if (mistake.cpp && !mistake.not_started) continue;  // the build makes it
            if (!mistake.not_started) {
                apply_mutant_edits(lab_folder, mistake.edit, s_.kit);
                continue;
            }
            for (const std::string& file : mistake.files) {
                const std::string text = make_starter(read_text_file(lab_folder / file), file, mistake.todo).text;
                std::ofstream(lab_folder / file, std::ios::binary | std::ios::trunc) << text;
            }
        }
    }, binary);
    return kits_.emplace(id, Kit{folder, in_cpp}).first->second;
}

std::string MistakePictures::key(const LabCases& lab, const KnownMistakes& known, const std::vector<std::size_t>& made,
                                 const GradeCase& c) {
    // The edits themselves, not the mistakes' names or texts: a mistake renamed or reworded keeps its pictures.
    std::string edits;
    for (const std::size_t m : made) {
        if (known.mistakes[m].not_started) {
            edits += "not started: " + known.mistakes[m].todo + "\n";
            continue;
        }
        const Json& edit = known.mistakes[m].edit;
        edits += "known mistake in " + edit.string_or("file", "") + "\n";
        const auto add = [&](const Json& e) { edits += "find " + e.string_at("find") + "\nreplace " + e.string_at("replace") + "\n"; };
        if (const Json* list = edit.find("edits")) {
            for (const Json& e : list->as_array()) add(e);
        } else {
            add(edit);
        }
    }
    return s_.reference_key(lab, c) + edits;
}

std::vector<LabRun> MistakePictures::render(const LabCases& lab, const KnownMistakes& known, const std::vector<std::size_t>& made,
                                            const std::vector<const GradeCase*>& cases) {
    std::vector<LabRun> runs(cases.size());
    std::vector<bool> have(cases.size(), false);
    std::vector<std::string> keys(cases.size());
    auto* cache = s_.options.reference_cache ? &s_.options.reference_cache->runs : nullptr;
    ReferenceStore* store = s_.options.stored_references ? s_.reference_store() : nullptr;
    looked_up_ += static_cast<int>(cases.size());
    for (std::size_t i = 0; i < cases.size(); ++i) {
        keys[i] = key(lab, known, made, *cases[i]);
        if (cache)
            if (const auto it = cache->find("mistake\n" + keys[i]); it != cache->end()) {
                runs[i] = it->second;
                have[i] = true;
                continue;
            }
        if (store) {
            if (std::optional<LabRun> stored = store->load(keys[i])) {
                runs[i] = std::move(*stored);
                have[i] = true;
                ++s_.mistake_store_hits;
            } else if (std::optional<LabRun> failed = store->load(keys[i] + kDidNotRender)) {
                ++s_.mistake_store_hits;
                // A mistake that does not render here (NaN on this driver): known without rendering it again.
                runs[i].status = CaseStatus::Error;
                runs[i].detail = failed->detail;
                have[i] = true;
            }
        }
    }
    std::unique_ptr<ServedLab> served;
    LabRunner runner;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        if (!have[i]) {
            if (!served) {
                const Kit& kit = kit_of(known, made);
                runner = LabRunner{kit.folder / "bin", kit.folder / "kit", false, s_.options.profile};
                if (!kit.cpp_mistake.empty())
                    runner.extra_environment.push_back(std::string(kKnownMistakeVariable) + "=" + kit.cpp_mistake);
                served = std::make_unique<ServedLab>(lab.lab);
                runner.served = served.get();
            }
            runs[i] = runner.render(lab.lab, lab, *cases[i], s_.limits(lab, false));
            ++rendered_;
            if (ReferenceStore* to = s_.reference_store()) {
                if (runs[i].status == CaseStatus::Passed) {
                    to->store(keys[i], runs[i]);
                } else {
                    // Kept as a passed entry of its own key, a pixel and the outcome in words (the store keeps passes).
                    LabRun marker;
                    marker.status = CaseStatus::Passed;
                    marker.image = Image(1, 1);
                    marker.detail = std::string(status_name(runs[i].status)) + ": " + runs[i].detail;
                    to->store(keys[i] + kDidNotRender, marker);
                }
            }
        }
        // The kit's own code draws the same every time: a mistake that did not render is remembered too.
        if (cache) cache->emplace("mistake\n" + keys[i], runs[i]);
    }
    return runs;
}

}  // namespace gsv
