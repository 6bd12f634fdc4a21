#pragma once
// The exit statuses of every lab binary, one meaning each. The grader tells a lab's failures apart by them
// (grader/src/run/lab_run.cpp's classify), so the labs and the grader name them from here, never as bare numbers.
namespace gsv {

enum ExitStatus {
    kExitOk = 0,
    kExitError = 1,        // any failure with a message: a shader that did not compile, a file that did not load
    kExitUsage = 2,        // the command line: an unknown option, a value out of range
    kExitUnsupported = 3,  // the GL context lacks what the lab needs (its last line says what)
    kExitNonFinite = 4,    // NaN or Inf in the image
};

}  // namespace gsv
