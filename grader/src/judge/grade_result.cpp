#include "grader/src/judge/grade_result.h"

namespace gsv {

const char* status_name(CaseStatus status) {
    switch (status) {
    case CaseStatus::Passed: return "passed";
    case CaseStatus::BuildError: return "build error";
    case CaseStatus::ShaderCompileError: return "shader compile error";
    case CaseStatus::ShaderLinkError: return "shader link error";
    case CaseStatus::Crash: return "crash";
    case CaseStatus::Timeout: return "timeout";
    case CaseStatus::MemoryLimit: return "memory limit";
    case CaseStatus::OutputFlood: return "output flood";
    case CaseStatus::MissingOutput: return "no output";
    case CaseStatus::WrongImage: return "wrong image";
    case CaseStatus::WrongData: return "wrong data";
    case CaseStatus::BlankImage: return "blank image";
    case CaseStatus::NonFinite: return "NaN";
    case CaseStatus::CopiedImage: return "copied image";
    case CaseStatus::TooSlow: return "too slow";
    case CaseStatus::MissingBinary: return "no binary";
    case CaseStatus::Unsupported: return "unsupported";
    case CaseStatus::Error: return "error";
    case CaseStatus::ReferenceFailed: return "reference failed";
    case CaseStatus::NotDone: return "not done";
    case CaseStatus::NeedsFirst: return "needs another TODO first";
    case CaseStatus::Refused: return "refused";
    case CaseStatus::WroteTooMuch: return "wrote too much";
    case CaseStatus::GpuMargin: return "GPU margin";
    case CaseStatus::KitFault: return "kit fault";
    }
    // Only reachable with a value cast from an out-of-range integer.
    return "unknown";
}

CaseResult case_row(const LabCases& lab, const GradeCase& c) {
    CaseResult r;
    r.lab = lab.lab;
    r.name = c.name;
    r.todo = c.todo;
    r.description = c.description;
    r.visibility = c.visibility;
    r.settings = c.settings;
    r.max_points = c.points;
    return r;
}

bool is_kit_fault(CaseStatus status) { return status == CaseStatus::ReferenceFailed || status == CaseStatus::KitFault; }

bool DataCheck::passed() const {
    for (const auto& a : arrays)
        if (!a.within()) return false;
    return true;
}

double GradeReport::score() const {
    double total = 0;
    for (const auto& r : results) total += r.points;
    return total;
}

double GradeReport::max_score() const {
    double total = 0;
    for (const auto& r : results) total += r.max_points;
    return total;
}

}  // namespace gsv
