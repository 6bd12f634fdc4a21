#include "grader/src/diagnose/shipped_diagnosis.h"

#include <algorithm>

namespace gsv {

ShippedDiagnosis diagnose_shipped(const KnownMistakePictures& shipped, const std::vector<ShippedFailure>& failed,
                                  const std::set<std::string>& passed, const std::filesystem::path& student_folder) {
    KnownMistakes known;
    known.lab = shipped.lab;
    known.lab_dir = shipped.lab_dir;
    for (const ShippedMistake& m : shipped.mistakes)
        known.mistakes.push_back({m.id, m.todo, m.says, m.sheet, Json::object(), m.not_started, {}, m.starter, false, ""});
    std::vector<std::string> failing;
    std::vector<std::set<std::string>> explains(known.mistakes.size()), fails(known.mistakes.size());
    for (std::size_t m = 0; m < known.mistakes.size(); ++m) fails[m] = shipped.mistakes[m].fails;
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
    prefer_confirmed_not_started(explains, known, student_folder);
    ShippedDiagnosis out;
    // Two mistakes drawn together: the student's picture against the two shipped ones composed (each block's change
    // added, or the colour's ratios multiplied), and against each alone.
    std::map<std::string, std::pair<PictureSignature, PictureSignature>> yours_and_golden;
    for (const ShippedFailure& f : failed)
        if (f.picture && f.golden && !f.picture->empty() && f.picture->width == f.golden->width && f.picture->height == f.golden->height)
            yours_and_golden[f.case_name] = {picture_signature(*f.picture, shipped.block), picture_signature(*f.golden, shipped.block)};
    const TogetherCheck together = [&](std::size_t a, std::size_t b, const std::string& c) {
        TogetherEvidence e;
        const auto it = yours_and_golden.find(c);
        const PictureSignature* first = shipped_signature(shipped, a, c);
        const PictureSignature* second = shipped_signature(shipped, b, c);
        if (it == yours_and_golden.end() || !first || !second) return e;
        const PictureSignature& yours = it->second.first;
        const PictureSignature& golden = it->second.second;
        const auto same_size = [&](const PictureSignature* p) {
            return p->colour.width == golden.colour.width && p->colour.height == golden.colour.height;
        };
        if (!same_size(first) || !same_size(second)) return e;  // shipped at another size: nothing to compose
        for (const Composition how : {Composition::Added, Composition::Multiplied}) {
            const PictureSignature both = composed_signature(*first, *second, golden, how);
            if (!signature_matches(yours, both, golden)) continue;
            e.matches = true;
            e.shows_first = e.shows_first || signature_matches(yours, both, *second);
            e.shows_second = e.shows_second || signature_matches(yours, both, *first);
        }
        return e;
    };
    out.diagnosis = name_mistakes_and_pairs(shipped.lab, failing, known.mistakes, explains, fails, together);
    out.not_started_cases = tell_not_started(out.diagnosis, known, student_folder);
    for (const MistakeFound& found : out.diagnosis.found) {
        const auto m = static_cast<std::size_t>(
            std::find_if(known.mistakes.begin(), known.mistakes.end(), [&](const KnownMistake& k) { return k.name == found.names.front(); }) -
            known.mistakes.begin());
        for (const std::string& c : found.cases) {
            out.mistake_of_case[c] = m;
            if (!explains[m].count(c)) out.drawn_together.insert(c);
        }
    }
    return out;
}

const PictureSignature* shipped_signature(const KnownMistakePictures& shipped, std::size_t m, const std::string& case_name) {
    const auto it = shipped.cases.find(case_name);
    if (it == shipped.cases.end()) return nullptr;
    for (const ShippedPicture& p : it->second)
        if (p.mistake == m) return &p.signature;
    return nullptr;
}

Image shipped_picture(const KnownMistakePictures& shipped, std::size_t m, const std::string& case_name, int width, int height) {
    const PictureSignature* signature = shipped_signature(shipped, m, case_name);
    return signature ? signature_picture(*signature, width, height) : Image{};
}

}  // namespace gsv
