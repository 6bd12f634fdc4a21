#include "grader/grade.h"

#include "common/error.h"
#include "common/image.h"
#include "common/json.h"
#include "grader/process.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

namespace fs = std::filesystem;

namespace gsv {
namespace {

std::vector<std::string> render_command(const fs::path& binary, const LabCases& lab, const GradeCase& c,
                                        const fs::path& png) {
    std::vector<std::string> argv{binary.string(), "render", "--size",
                                  std::to_string(lab.width) + "x" + std::to_string(lab.height), "--out", png.string(),
                                  "--frames", "1", "--warmup", "0"};
    for (const auto& s : c.settings) {
        argv.push_back("--set");
        argv.push_back(s);
    }
    return argv;
}

std::string last_lines(const std::string& text, int count) {
    std::size_t pos = text.size();
    while (pos > 0 && (text[pos - 1] == '\n')) --pos;
    for (int i = 0; i < count && pos != std::string::npos && pos > 0; ++i) pos = text.rfind('\n', pos - 1);
    return text.substr(pos == std::string::npos ? 0 : pos + (pos > 0 ? 1 : 0));
}

// Tells the failure classes apart from the exit status the lab framework gives each (common/app.h).
CaseStatus classify(const ProcessResult& r, std::string& detail) {
    if (r.failed_to_start) { detail = "the lab binary could not be started"; return CaseStatus::MissingBinary; }
    if (r.timed_out) { detail = "killed after the time limit (an endless loop in a shader?)"; return CaseStatus::Timeout; }
    if (r.signal != 0) { detail = std::string("crashed with signal ") + std::to_string(r.signal) + (r.signal == 11 ? " (segmentation fault)" : ""); return CaseStatus::Crash; }
    switch (r.exit_code) {
    case 0: return CaseStatus::Passed;
    case 3: detail = last_lines(r.output, 1); return CaseStatus::Unsupported;
    case 4: detail = "NaN or Inf in the image"; return CaseStatus::NonFinite;
    default: break;
    }
    if (r.output.find("shader compile error") != std::string::npos || r.output.find("shader link error") != std::string::npos) {
        const auto at = r.output.find("shader ");
        detail = r.output.substr(at, r.output.find('\n', at) - at);
        return CaseStatus::ShaderError;
    }
    detail = last_lines(r.output, 1);
    return CaseStatus::Error;
}

}  // namespace

const char* status_name(CaseStatus status) {
    switch (status) {
    case CaseStatus::Passed: return "passed";
    case CaseStatus::WrongImage: return "wrong image";
    case CaseStatus::NonFinite: return "NaN";
    case CaseStatus::MissingBinary: return "no binary";
    case CaseStatus::ShaderError: return "shader error";
    case CaseStatus::Crash: return "crash";
    case CaseStatus::Timeout: return "timeout";
    case CaseStatus::MissingOutput: return "no output";
    case CaseStatus::Unsupported: return "unsupported";
    case CaseStatus::Error: return "error";
    case CaseStatus::ReferenceFailed: return "reference failed";
    }
    return "?";
}

std::vector<CaseResult> grade(const GradeOptions& options, void (*progress)(const CaseResult&)) {
    std::vector<CaseResult> results;
    auto record = [&](const CaseResult& r) {
        results.push_back(r);
        if (progress) progress(r);
    };
    for (const auto& file : case_files(options.kit_root)) {
        const LabCases lab = load_lab_cases(file);
        if (!options.labs.empty() &&
            std::find(options.labs.begin(), options.labs.end(), lab.lab) == options.labs.end())
            continue;
        const fs::path student = fs::absolute(options.bin_dir) / lab.lab;
        const fs::path solution = fs::absolute(options.bin_dir) / (lab.lab + "_solution");
        const bool live = !options.self_check && fs::exists(solution);
        ProcessLimits limits;
        const double timeout_s = options.timeout_s > 0 ? options.timeout_s : lab.timeout_s;
        limits.timeout = std::chrono::milliseconds(static_cast<long>(timeout_s * 1000));
        for (const auto& c : lab.cases) {
            CaseResult r;
            r.lab = lab.lab;
            r.name = c.name;
            r.todo = c.todo;
            r.visibility = c.visibility;
            r.max_points = c.points;
            // Absolute: each lab process runs inside this folder, so a relative --out would nest twice.
            const fs::path dir = fs::absolute(options.out_dir) / lab.lab / c.name;
            fs::create_directories(dir);
            const fs::path golden = fs::absolute(options.kit_root) / "grader" / "golden" / lab.lab / (c.name + ".png");
            const fs::path expected_png = dir / "expected.png";
            if (options.update_goldens) {
                const ProcessResult ref = run_process(render_command(solution, lab, c, golden), dir, limits);
                std::string detail;
                r.status = classify(ref, detail);
                r.detail = r.status == CaseStatus::Passed ? "wrote " + golden.string() : detail;
                r.output = ref.output;
                record(r);
                continue;
            }
            if (live) {
                r.reference = "live";
                const ProcessResult ref = run_process(render_command(solution, lab, c, expected_png), dir, limits);
                std::string detail;
                if (classify(ref, detail) != CaseStatus::Passed) {
                    r.status = CaseStatus::ReferenceFailed;
                    r.detail = "the reference solution failed: " + detail;
                    r.output = ref.output;
                    record(r);
                    continue;
                }
            } else {
                r.reference = "golden";
                if (!fs::exists(golden)) {
                    r.status = CaseStatus::ReferenceFailed;
                    r.detail = "no golden image " + golden.string();
                    record(r);
                    continue;
                }
                fs::copy_file(golden, expected_png, fs::copy_options::overwrite_existing);
            }
            const fs::path actual_png = dir / "actual.png";
            fs::remove(actual_png);
            const ProcessResult run = fs::exists(student)
                                          ? run_process(render_command(student, lab, c, actual_png), dir, limits)
                                          : ProcessResult{-1, 0, false, true, "", 0};
            r.seconds = run.seconds;
            r.output = run.output;
            r.status = classify(run, r.detail);
            if (r.status == CaseStatus::MissingBinary && !fs::exists(student))
                r.detail = "no binary " + student.string() + " (did the lab build?)";
            if (r.status == CaseStatus::Passed) {
                if (!fs::exists(actual_png)) {
                    r.status = CaseStatus::MissingOutput;
                    r.detail = "the lab exited 0 but wrote no image";
                } else {
                    try {
                        const Image actual = read_png(actual_png);
                        const Image expected = read_png(expected_png);
                        const ImageTolerance tolerance = live ? lab.live_tolerance : lab.golden_tolerance;
                        const ImageDiff diff = compare_images(actual, expected, tolerance);
                        if (diff.within(tolerance)) {
                            r.points = c.points;
                            r.detail = diff.max_channel_diff == 0 ? "identical" : "max diff " + std::to_string(diff.max_channel_diff);
                        } else {
                            r.status = CaseStatus::WrongImage;
                            r.detail = diff.summary();
                            if (!diff.size_mismatch) write_png(dir / "diff.png", difference_heatmap(actual, expected));
                        }
                    } catch (const Error& e) {
                        r.status = CaseStatus::MissingOutput;
                        r.detail = e.what();
                    }
                }
            }
            record(r);
        }
    }
    return results;
}

std::string score_table(const std::vector<CaseResult>& results) {
    std::ostringstream out;
    char line[512];
    std::snprintf(line, sizeof line, "%-7s %-12s %-7s %-14s %8s  %s\n", "lab", "case", "todo", "status", "points", "detail");
    out << line;
    std::map<std::string, std::pair<double, double>> per_lab;
    double total = 0, max_total = 0;
    for (const auto& r : results) {
        std::snprintf(line, sizeof line, "%-7s %-12s %-7s %-14s %4.1f/%-3.1f  %s\n", r.lab.c_str(), r.name.c_str(),
                      r.todo.c_str(), status_name(r.status), r.points, r.max_points, r.detail.substr(0, 100).c_str());
        out << line;
        per_lab[r.lab].first += r.points;
        per_lab[r.lab].second += r.max_points;
        total += r.points;
        max_total += r.max_points;
    }
    out << "\n";
    for (const auto& [lab, score] : per_lab) {
        std::snprintf(line, sizeof line, "%-7s %5.1f / %-5.1f\n", lab.c_str(), score.first, score.second);
        out << line;
    }
    std::snprintf(line, sizeof line, "%-7s %5.1f / %-5.1f\n", "total", total, max_total);
    out << line;
    return out.str();
}

std::string results_json(const std::vector<CaseResult>& results) {
    Json root = Json::object();
    double score = 0;
    Json tests = Json::array();
    for (const auto& r : results) {
        Json t = Json::object();
        t["name"] = r.lab + "/" + r.name + " (" + r.todo + ")";
        t["score"] = r.points;
        t["max_score"] = r.max_points;
        t["status"] = r.status == CaseStatus::Passed ? "passed" : "failed";
        t["output"] = std::string(status_name(r.status)) + ": " + r.detail + (r.output.empty() ? "" : "\n" + r.output);
        t["visibility"] = r.visibility == "hidden" ? "after_due_date" : "visible";
        Json tags = Json::array();
        tags.push_back(r.todo);
        t["tags"] = tags;
        tests.push_back(t);
        score += r.points;
    }
    root["score"] = score;
    root["tests"] = tests;
    return root.dump(2) + "\n";
}

}  // namespace gsv
