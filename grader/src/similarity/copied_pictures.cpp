#include "grader/src/similarity/copied_pictures.h"

#include "common/core/error.h"
#include "common/core/fnv1a.h"
#include "common/image/image.h"
#include "grader/src/batch/batch_record.h"
#include "grader/src/report/report.h"

#include <map>
#include <set>
#include <optional>
#include <tuple>

namespace fs = std::filesystem;

namespace gsv {
namespace {

std::optional<Image> picture_at(const fs::path& file) {
    try {
        return read_png(file);
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

std::string pixels_key(const Image& image) {
    Fnv1a hash;
    hash.add(std::to_string(image.width) + "x" + std::to_string(image.height));
    hash.add(reinterpret_cast<const char*>(image.rgba.data()), image.rgba.size());
    return hash.hex();
}

struct WrongPicture {
    std::string student, todo, picture, expected;  // pictures relative to the batch's --out
    bool mistakes_looked_for = false;
};

}  // namespace

CopiedPictures find_copied_pictures(const fs::path& out_dir) {
    CopiedPictures found;
    if (!fs::is_regular_file(out_dir / "batch.json")) return found;
    const BatchRecord record = read_batch_record(out_dir);
    found.batch_found = true;
    // (lab, case, pixels' hash) -> the students who drew that wrong picture, in the class's order.
    std::map<std::tuple<std::string, std::string, std::string>, std::vector<WrongPicture>> by_pixels;
    for (const BatchEntry& e : record.entries) {
        if (!e.graded) continue;
        GradeReport report;
        try {
            report = read_report_json(out_dir / e.name / "report.json");
        } catch (const Error& error) {
            found.notes.push_back(error.what());
            continue;
        }
        ++found.students;
        // A TODO left as the starter has it draws the same picture for everyone who left it: no sign of a copy.
        std::set<std::pair<std::string, std::string>> not_started;
        for (const auto& d : report.diagnoses)
            for (const std::string& todo : d.not_started) not_started.insert({d.lab, todo});
        for (const CaseResult& r : report.results) {
            if (not_started.count({r.lab, r.todo})) continue;
            // A wrong image no known mistake explains. The starter's not-done colour, a blank picture and a case that waits
            // for another TODO are what many students hand in alike.
            if (r.kind != "image" || r.status != CaseStatus::WrongImage || !r.mistake.empty() || r.actual_png.empty()) continue;
            const std::string relative = (fs::path(e.name) / r.actual_png).generic_string();
            const std::optional<Image> picture = picture_at(out_dir / relative);
            if (!picture) {
                found.notes.push_back(relative + ": not a PNG that reads");
                continue;
            }
            ++found.wrong_pictures;
            const bool looked = report.diagnose == "all" || (report.diagnose == "public" && r.visibility == "public");
            const std::string expected = r.expected_png.empty() ? "" : (fs::path(e.name) / r.expected_png).generic_string();
            by_pixels[{r.lab, r.name, pixels_key(*picture)}].push_back({e.name, r.todo, relative, expected, looked});
        }
    }
    for (const auto& [key, drew] : by_pixels) {
        if (drew.size() != 2) continue;
        // The hash says which to compare; the pixels decide.
        const std::optional<Image> a = picture_at(out_dir / drew[0].picture), b = picture_at(out_dir / drew[1].picture);
        if (!a || !b || a->width != b->width || a->height != b->height || a->rgba != b->rgba) continue;
        PicturePair pair;
        pair.lab = std::get<0>(key);
        pair.case_name = std::get<1>(key);
        pair.todo = drew[0].todo;
        pair.a = drew[0].student;
        pair.b = drew[1].student;
        pair.picture = drew[0].picture;
        pair.expected = drew[0].expected;
        pair.mistakes_looked_for = drew[0].mistakes_looked_for && drew[1].mistakes_looked_for;
        found.pairs.push_back(pair);
    }
    return found;
}

}  // namespace gsv
