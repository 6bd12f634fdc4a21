#include "grader/src/update/mistake_update.h"

#include "common/app/kit_layout.h"
#include "common/app/known_mistake_pictures.h"
#include "common/core/error.h"
#include "grader/src/diagnose/diagnosis.h"
#include "grader/src/grade/mistake_pictures.h"
#include "grader/src/grade/session.h"

#include <cstdio>
#include <map>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// Ids that say which TODO, never what the edit was: "L01-T1 a", "L01-T1 b", ...; "L01-T1 not started".
std::string mistake_id(const KnownMistake& m, std::map<std::string, int>& count) {
    if (m.not_started) return m.todo + " not started";
    const int n = count[m.todo]++;
    std::string letters;
    for (int k = n;; k = k / 26 - 1) {
        letters.insert(letters.begin(), static_cast<char>('a' + k % 26));
        if (k < 26) break;
    }
    return m.todo + " " + letters;
}

CaseResult write_lab(GradingSession& s, MistakePictures& pictures, const LabCases& lab) {
    GradeCase whole;
    whole.name = "known mistakes";
    whole.todo = "";
    CaseResult r = s.result_for(lab, whole);
    r.kind = "mistakes";
    const KnownMistakes known = known_mistakes(s.kit, lab.lab);
    if (known.mistakes.empty()) {
        r.status = CaseStatus::Error;
        r.detail = "no known mistakes (tests/mutants/" + lab.lab + ".json)";
        return r;
    }
    std::vector<const GradeCase*> cases;
    std::map<std::string, Image> golden;
    for (const GradeCase& c : lab.cases)
        if (c.visibility == "public") {
            cases.push_back(&c);
            golden[c.name] = read_png(KitLayout{s.kit}.golden_image(lab.lab, c.name));
        }
    KnownMistakePictures out;
    out.lab = lab.lab;
    out.lab_dir = known.lab_dir;
    out.block = signature_block(lab.width, lab.height);
    out.inputs = mistake_pictures_inputs(s.kit, lab.lab, known.lab_dir);
    std::map<std::string, int> count;
    int kept = 0;
    for (std::size_t m = 0; m < known.mistakes.size(); ++m) {
        const KnownMistake& k = known.mistakes[m];
        ShippedMistake shipped{mistake_id(k, count), k.todo, k.says, k.sheet, k.not_started, k.starter, {}};
        const std::vector<LabRun> runs = pictures.render(lab, known, {m}, cases);
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const GradeCase& c = *cases[i];
            if (runs[i].status != CaseStatus::Passed) {
                shipped.fails.insert(c.name);  // a mistake that does not render here fails the case, picture or none
                continue;
            }
            const ExpectedRender expected{golden.at(c.name), std::nullopt, false};
            if (!mistake_fails(lab, c, runs[i], expected, s.kit)) continue;
            shipped.fails.insert(c.name);
            if (runs[i].image && runs[i].image->width == lab.width && runs[i].image->height == lab.height) {
                out.cases[c.name].push_back({out.mistakes.size(), picture_signature(*runs[i].image, out.block)});
                ++kept;
            }
        }
        out.mistakes.push_back(std::move(shipped));
    }
    write_known_mistake_pictures(s.kit, out);
    r.status = CaseStatus::Passed;
    r.detail = "wrote " + known_mistakes_file(s.kit, lab.lab).string() + ": " + std::to_string(out.mistakes.size()) +
               " mistakes, " + std::to_string(kept) + " pictures of " + std::to_string(cases.size()) + " public cases";
    return r;
}

}  // namespace

GradeReport update_mistake_pictures(const GradeOptions& options, const std::function<void(const GradeProgress&)>& progress) {
    GradingSession s(options, progress, RunPurpose::UpdateGoldens);
    s.set_up();
    MistakePictures pictures(s);
    for (const LabCases& lab : s.labs) {
        try {
            s.record(write_lab(s, pictures, lab));
        } catch (const Error& e) {
            GradeCase whole;
            whole.name = "known mistakes";
            CaseResult r = s.result_for(lab, whole);
            r.status = CaseStatus::Error;
            r.detail = e.what();
            s.record(r);
        }
    }
    return s.finish();
}

}  // namespace gsv
