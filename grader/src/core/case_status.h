#pragma once
// How a check ended: the one word every floor of the grader says of a case, from the run that could not start it to the
// report that prints it, so it lives on the lowest floor (CONTRIBUTING.md, "Floors").
namespace gsv {

// Every way a check can end, told apart so the student knows what to fix.
enum class CaseStatus {
    Passed,
    BuildError,          // the lab's C++ did not compile or link
    ShaderCompileError,  // file:line and the source line are in the output
    ShaderLinkError,
    Crash,               // killed by a signal (segfault, abort)
    Timeout,             // killed after the wall-clock limit
    MemoryLimit,         // ran out of its address-space limit
    OutputFlood,         // printed far more than any lab should; killed
    MissingOutput,       // exited 0 without a valid PNG
    WrongImage,
    WrongData,           // the image passed, but the numbers the lab hands in (its particle buffer) are wrong
    BlankImage,          // one flat colour where the reference has a picture
    NonFinite,           // NaN or Inf in the float image
    CopiedImage,         // byte for byte a committed golden image of another case
    TooSlow,             // frame time over the reference's beyond the case's band
    MissingBinary,
    Unsupported,         // the GL context lacks what the lab needs
    Error,               // any other non-zero exit
    ReferenceFailed,     // the reference itself failed: not the student's fault, scored 0 and flagged
    NotDone,             // the starter's not-done colour where the reference draws: the TODO is still open
    NeedsFirst,          // fails, and a TODO it depends on ("needs") fails its own cases: that one first
    Refused,             // what it handed in breaks the hand-in's rules: a message over its limit or malformed, a timed
                         // frame before its challenge, or one that is not the frame drawn with the challenge's settings
    WroteTooMuch,        // filled its working folder (size or number of files) to the limit
    GpuMargin,           // against a golden made on another renderer: off by more than the case's budget, but within the
                         // margin renderers differ by (cross_implementation_tolerance, grader/cases.h); no points
    KitFault,            // the kit or the grader's set-up failed where the student's files play no part (a submission
                         // project that does not configure even without them): scored 0 and flagged, like ReferenceFailed
};
// The last status, for code that reads them back by name.
inline constexpr CaseStatus kLastCaseStatus = CaseStatus::KitFault;
const char* status_name(CaseStatus status);
// The reference or the kit failed, not the student (ReferenceFailed, KitFault): reported apart from the student's
// failures, and a run with one gives no grade (gsv-grade exits kGradeKitFault).
bool is_kit_fault(CaseStatus status);

}  // namespace gsv
