#include "grader/src/grade/diagnose_lab.h"

#include "common/app/kit_layout.h"
#include "common/app/known_mistake_pictures.h"
#include "common/core/error.h"
#include "common/image/image.h"
#include "grader/src/diagnose/shipped_diagnosis.h"
#include "grader/src/judge/needs.h"

#include <algorithm>
#include <optional>

namespace fs = std::filesystem;

namespace gsv {
namespace {

// At most this many rounds: a mistake alone, then made together with one or two named before it.
constexpr int kRounds = 3;

std::size_t index_of(const KnownMistakes& known, const std::string& name) {
    return static_cast<std::size_t>(
        std::find_if(known.mistakes.begin(), known.mistakes.end(), [&](const KnownMistake& k) { return k.name == name; }) -
        known.mistakes.begin());
}

// Whether the mistakes `made` pass every case the student's lab passed (their pictures kept and rendered like any).
bool agrees_with_passes(GradingSession& s, MistakePictures& pictures, const LabCases& lab, const KnownMistakes& known,
                        const std::vector<std::size_t>& made, const std::vector<PassedRender>& passed) {
    if (passed.empty()) return true;
    std::vector<const GradeCase*> cases;
    for (const PassedRender& p : passed) cases.push_back(p.c);
    const std::vector<LabRun> runs = pictures.render(lab, known, made, cases);
    for (std::size_t i = 0; i < passed.size(); ++i)
        if (runs[i].status != CaseStatus::Passed || mistake_fails(lab, *passed[i].c, runs[i], passed[i].expected, s.kit)) return false;
    return true;
}

void add_note(GradeReport& report, const std::string& line) {
    if (report.diagnosis_note.find(line) != std::string::npos) return;
    report.diagnosis_note += (report.diagnosis_note.empty() ? "" : "; ") + line;
}

// The student's copy of the lab: its folder in labs/, or solutions/ where the kit's own reference is graded.
fs::path student_folder(GradingSession& s, const std::string& lab_dir) {
    const KitLayout student{s.student_kit()};
    return fs::exists(student.labs() / lab_dir) ? student.labs() / lab_dir : student.solutions() / lab_dir;
}

// The report's row of a failing case.
CaseResult& row_of(GradingSession& s, const std::vector<FailedRender>& failed, const std::string& name) {
    return s.report.results[std::find_if(failed.begin(), failed.end(), [&](const FailedRender& x) { return x.c->name == name; })->row];
}

// An explained row: its mistake, and that mistake's picture beside the student's.
void mark_explained(GradingSession& s, const LabCases& lab, CaseResult& r, const MistakeFound& found, const Image& picture) {
    r.mistake = found.says;
    r.mistake_todo = found.todo;
    r.mistake_sheet = found.sheet;
    if (picture.empty()) return;  // drawn by two mistakes together: no one picture of it
    const fs::path png = s.out / lab.lab / r.name / "mistake.png";
    write_png(png, picture);
    r.mistake_png = fs::relative(png, s.out).generic_string();
}

// The mistakes found, told from TODOs not started, each explained row marked with its mistake and its picture.
void name_found(GradingSession& s, const LabCases& lab, const KnownMistakes& known, const std::vector<FailedRender>& failed,
                const std::map<std::pair<std::size_t, std::string>, Image>& pictures_of, LabDiagnosis& d) {
    for (const auto& [name, todo] : tell_not_started(d, known, student_folder(s, known.lab_dir)))
        row_of(s, failed, name).mistake_todo = todo;  // "mistake" stays empty: not started
    for (const MistakeFound& found : d.found) {
        const std::size_t m = index_of(known, found.names.front());
        for (const std::string& name : found.cases) mark_explained(s, lab, row_of(s, failed, name), found, pictures_of.at({m, name}));
    }
}

// The self-check's diagnosis from the pictures the kit ships (common/app/known_mistake_pictures.h): each mistake alone
// (no two made together: their pictures are not shipped), a candidate only where the cases its picture fails are all
// cases the student failed. False where this run does not use them (instructor grading, none shipped for the lab).
bool shipped_diagnosis(GradingSession& s, const LabCases& lab, const LabRenders& renders, LabDiagnosis& d) {
    if (s.options.mistake_pictures == MistakePictureSource::Rendered) return false;
    // Default: where the failures were judged against the goldens (a self-check, or a kit without the solutions), as
    // the pictures shipped beside them were.
    const bool against_goldens = std::none_of(renders.failed.begin(), renders.failed.end(),
                                              [](const FailedRender& f) { return f.expected.live; });
    if (s.options.mistake_pictures == MistakePictureSource::Default && !against_goldens) return false;
    KnownMistakePictures shipped;
    try {
        shipped = read_known_mistake_pictures(s.kit, lab.lab);
    } catch (const Error& e) {
        add_note(s.report, e.what());
        return true;  // said; a broken file is not made up for by rendering
    }
    if (shipped.empty()) return false;
    std::set<std::string> passed;
    for (const PassedRender& p : renders.passed) passed.insert(p.c->name);
    std::vector<ShippedFailure> failed;
    for (const FailedRender& f : renders.failed)
        failed.push_back({f.c->name, f.student.image ? &*f.student.image : nullptr, &f.expected.image});
    ShippedDiagnosis found = diagnose_shipped(shipped, failed, passed, student_folder(s, shipped.lab_dir));
    for (const auto& [name, todo] : found.not_started_cases) row_of(s, renders.failed, name).mistake_todo = todo;
    for (const MistakeFound& f : found.diagnosis.found)
        for (const std::string& name : f.cases)
            mark_explained(s, lab, row_of(s, renders.failed, name), f,
                           found.drawn_together.count(name)
                               ? Image{}
                               : shipped_picture(shipped, found.mistake_of_case.at(name), name, lab.width, lab.height));
    // The TODOs whose cases were not done, then those a starter's picture explains.
    for (const std::string& t : found.diagnosis.not_started)
        if (std::find(d.not_started.begin(), d.not_started.end(), t) == d.not_started.end()) d.not_started.push_back(t);
    found.diagnosis.not_started = std::move(d.not_started);
    d = std::move(found.diagnosis);
    return true;
}

// The best pair consistent with the failures left (ranking.h, consistent_pairs) whose two mistakes, made together, draw
// every one of them as the student did and pass what the student passed; its pictures kept. Only the first few pairs
// are made: each costs a render of the cases left.
std::optional<MistakePair> verified_pair(GradingSession& s, MistakePictures& pictures, const LabCases& lab, const KnownMistakes& known,
                                         const std::vector<const FailedRender*>& left, const std::vector<PassedRender>& passed,
                                         const std::vector<std::set<std::string>>& explains,
                                         const std::vector<std::set<std::string>>& fails,
                                         std::map<std::pair<std::size_t, std::string>, Image>& pictures_of) {
    constexpr std::size_t kPairsMade = 3;
    std::vector<const GradeCase*> cases;
    std::vector<std::string> names;
    for (const FailedRender* f : left) {
        cases.push_back(f->c);
        names.push_back(f->c->name);
    }
    const std::vector<MistakePair> pairs = consistent_pairs(names, names, known.mistakes, explains, fails, {});
    for (std::size_t p = 0; p < pairs.size() && p < kPairsMade; ++p) {
        const std::vector<std::size_t> made{pairs[p].first, pairs[p].second};
        std::vector<LabRun> runs;
        try {
            runs = pictures.render(lab, known, made, cases);
        } catch (const std::exception&) {
            continue;  // the two edits cannot be made together
        }
        bool all = true;
        for (std::size_t i = 0; i < left.size() && all; ++i)
            all = student_matches(lab, *left[i]->c, left[i]->student, runs[i]) && mistake_fails(lab, *left[i]->c, runs[i], left[i]->expected, s.kit);
        if (!all || !agrees_with_passes(s, pictures, lab, known, made, passed)) continue;
        for (std::size_t i = 0; i < left.size(); ++i)
            if (!explains[pairs[p].first].count(names[i])) pictures_of[{pairs[p].second, names[i]}] = *runs[i].image;
        return pairs[p];
    }
    return std::nullopt;
}

}  // namespace

bool diagnoses(const GradingSession& s, const GradeCase& c) {
    if (s.diagnose == DiagnoseCases::Off) return false;
    return s.diagnose == DiagnoseCases::All || c.visibility == "public";
}

void diagnose_lab(GradingSession& s, MistakePictures& pictures, const LabCases& lab, std::size_t first,
                  const LabRenders& renders) {
    const std::vector<FailedRender>& failed = renders.failed;
    if (s.diagnose == DiagnoseCases::Off) return;
    LabDiagnosis d;
    d.lab = lab.lab;
    for (std::size_t i = first; i < s.report.results.size(); ++i) {
        const CaseResult& r = s.report.results[i];
        if (r.kind == "image" && r.status == CaseStatus::NotDone && (s.diagnose == DiagnoseCases::All || r.visibility == "public") &&
            std::find(d.not_started.begin(), d.not_started.end(), r.todo) == d.not_started.end())
            d.not_started.push_back(r.todo);
    }
    std::vector<std::string> failing;
    for (const FailedRender& f : failed) failing.push_back(f.c->name);
    if (!failed.empty() && shipped_diagnosis(s, lab, renders, d)) {
        // the self-check: the pictures the kit ships
    } else if (!failed.empty()) {
        KnownMistakes known;
        try {
            known = known_mistakes(s.kit, lab.lab);
        } catch (const Error& e) {
            add_note(s.report, e.what());
        }
        if (known.mistakes.empty()) {
            add_note(s.report, "no known mistakes of " + lab.lab + " in this kit (tests/mutants/" + lab.lab + ".json)");
        } else if (!s.walls_up()) {
            add_note(s.report, "the known mistakes' pictures are made only where the allow-list walls are up");
            known.mistakes.clear();
        } else if (!fs::exists(s.bin / (lab.lab + "_solution"))) {
            add_note(s.report, "the known mistakes' pictures need " + lab.lab + "_solution, which this build lacks");
            known.mistakes.clear();
        } else if (!fs::exists(s.bin / (lab.lab + "_mistakes"))) {
            const auto before = known.mistakes.size();
            known.mistakes.erase(std::remove_if(known.mistakes.begin(), known.mistakes.end(), [](const KnownMistake& m) { return m.cpp; }),
                                 known.mistakes.end());
            if (known.mistakes.size() != before)
                add_note(s.report, "the known C++ mistakes' pictures need " + lab.lab + "_mistakes, which this build lacks: they are not named");
        }
        // Rounds: first each mistake alone; then, for the failures left, each other mistake made together with those
        // named so far (two mistakes in two TODOs draw a case both touch as neither draws it alone).
        std::map<std::pair<std::size_t, std::string>, Image> pictures_of;  // (mistake, case) -> its picture, where it explains
        std::vector<std::size_t> named;
        std::vector<const FailedRender*> left;
        for (const FailedRender& f : failed) left.push_back(&f);
        d.failing = failing;
        for (int round = 0; round < kRounds && !left.empty() && !known.mistakes.empty(); ++round) {
            std::vector<const GradeCase*> left_cases;
            std::vector<std::string> left_names;
            for (const FailedRender* f : left) {
                left_cases.push_back(f->c);
                left_names.push_back(f->c->name);
            }
            std::vector<std::set<std::string>> explains(known.mistakes.size()), fails(known.mistakes.size());
            for (std::size_t m = 0; m < known.mistakes.size(); ++m) {
                if (std::find(named.begin(), named.end(), m) != named.end()) continue;
                std::vector<std::size_t> made = named;
                made.push_back(m);
                std::vector<LabRun> runs;
                try {
                    runs = pictures.render(lab, known, made, left_cases);
                } catch (const std::exception& e) {
                    if (round == 0) add_note(s.report, std::string("a known mistake's picture could not be made: ") + e.what());
                    continue;  // later rounds: mistakes that cannot be made together with those named
                }
                std::set<std::string> explained;
                for (std::size_t i = 0; i < left.size(); ++i) {
                    if (!mistake_fails(lab, *left[i]->c, runs[i], left[i]->expected, s.kit)) continue;
                    fails[m].insert(left[i]->c->name);
                    if (student_matches(lab, *left[i]->c, left[i]->student, runs[i])) explained.insert(left[i]->c->name);
                }
                if (explained.empty()) continue;
                // It must also agree with what the student got right: a case they passed, it passes too.
                if (!agrees_with_passes(s, pictures, lab, known, made, renders.passed)) continue;
                for (std::size_t i = 0; i < left.size(); ++i)
                    if (explained.count(left[i]->c->name)) pictures_of.emplace(std::make_pair(m, left[i]->c->name), *runs[i].image);
                explains[m] = explained;
            }
            prefer_confirmed_not_started(explains, known, student_folder(s, known.lab_dir));
            const LabDiagnosis ranked = rank_mistakes(lab.lab, left_names, known.mistakes, explains);
            // A mistake is named only where it explains at least half the failures still left when its turn comes: one
            // that matches a case or two of many is a coincidence of pictures (lab 03's wrong slices look alike
            // whatever chose them), not evidence.
            std::set<std::string> newly;
            std::size_t remaining = left.size();
            for (MistakeFound f : ranked.found) {
                if (f.cases.size() * 2 < remaining) break;
                remaining -= f.cases.size();
                newly.insert(f.cases.begin(), f.cases.end());
                f.with_earlier = round > 0;
                named.push_back(index_of(known, f.names.front()));
                d.found.push_back(std::move(f));
            }
            if (newly.empty() && round == 0) {
                // None alone explains half: two mistakes in two TODOs, each drawing the cases only it touches, made
                // together to see the cases both touch.
                if (const auto pair = verified_pair(s, pictures, lab, known, left, renders.passed, explains, fails, pictures_of)) {
                    add_pair(d, *pair, true, known.mistakes, explains, fails);
                    named.push_back(pair->first);
                    named.push_back(pair->second);
                    left.clear();
                }
                break;
            }
            if (newly.empty()) break;
            std::vector<const FailedRender*> still;
            for (const FailedRender* f : left)
                if (!newly.count(f->c->name)) still.push_back(f);
            left = still;
        }
        for (const FailedRender* f : left) d.unexplained.push_back(f->c->name);
        name_found(s, lab, known, failed, pictures_of, d);
    }
    // A TODO not started: where to begin, a TODO whose case needs no other.
    if (!d.not_started.empty()) d.way_in = way_in(lab, s.report.results, first);
    if (!d.failing.empty() || !d.not_started.empty()) s.report.diagnoses.push_back(std::move(d));
}

}  // namespace gsv
