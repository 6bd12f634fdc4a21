#include "grader/src/core/case_status.h"

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

bool is_kit_fault(CaseStatus status) { return status == CaseStatus::ReferenceFailed || status == CaseStatus::KitFault; }

}  // namespace gsv
