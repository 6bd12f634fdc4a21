#include "grader/src/diagnose/shipped_diagnosis.h"

#include <algorithm>

namespace gsv {

ShippedDiagnosis diagnose_shipped(const KnownMistakePictures& shipped, const std::vector<ShippedFailure>& failed,
                                  const std::set<std::string>& passed, const std::filesystem::path& student_folder) {
    KnownMistakes known;
    known.lab = shipped.lab;
    known.lab_dir = shipped.lab_dir;
    for (const ShippedMistake& m : shipped.mistakes)
        known.mistakes.push_back({m.id, m.todo, m.says, m.sheet, Json::object(), m.not_started, {}, m.starter});
    std::vector<std::string> failing;
    std::vector<std::set<std::string>> explains(known.mistakes.size());
    for (const ShippedFailure& f : failed) {
        failing.push_back(f.case_name);
        if (!f.picture || !f.golden || f.picture->empty()) continue;
        for (const std::size_t m : matching_mistakes(shipped, f.case_name, *f.picture, *f.golden)) {
            const std::set<std::string>& fails = shipped.mistakes[m].fails;
            // It must agree with what the student got right: a case they passed, its picture passes too.
            if (std::any_of(fails.begin(), fails.end(), [&](const std::string& c) { return passed.count(c) > 0; })) continue;
            explains[m].insert(f.case_name);
        }
    }
    ShippedDiagnosis out;
    out.diagnosis = name_mistakes(shipped.lab, failing, known.mistakes, explains);
    out.not_started_cases = tell_not_started(out.diagnosis, known, student_folder);
    for (const MistakeFound& found : out.diagnosis.found) {
        const auto m = static_cast<std::size_t>(
            std::find_if(known.mistakes.begin(), known.mistakes.end(), [&](const KnownMistake& k) { return k.name == found.names.front(); }) -
            known.mistakes.begin());
        for (const std::string& c : found.cases) out.mistake_of_case[c] = m;
    }
    return out;
}

Image shipped_picture(const KnownMistakePictures& shipped, std::size_t m, const std::string& case_name, int width, int height) {
    const auto it = shipped.cases.find(case_name);
    if (it == shipped.cases.end()) return {};
    for (const ShippedPicture& p : it->second)
        if (p.mistake == m) return signature_picture(p.signature, width, height);
    return {};
}

}  // namespace gsv
