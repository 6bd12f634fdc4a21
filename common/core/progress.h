#pragma once
// A progress line with an estimate of the time left, for work that takes minutes (sweeps, batch grading).
// On a terminal one line is rewritten in place; anywhere else (a CI log, a file) each step is one line,
// and nothing else is printed.
#include <chrono>
#include <cstdio>
#include <string>

namespace gsv {

// "40 s", "3 min 20 s", "2 h 05 min": a duration as a person reads it (whole seconds).
std::string duration_text(double seconds);
// "[3/12] what, about 40 s left": the time left is the mean time of the steps done times the steps left;
// "[12/12] what, done in 2 min" at the end, and no estimate before the first step is done.
std::string progress_text(int done, int total, const std::string& what, double elapsed_seconds);

class Progress {
public:
    // `total` steps; the clock starts now.
    Progress(std::string task, int total, std::FILE* stream = stderr);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;
    // One more step done, `what` naming it.
    void step(const std::string& what);
    // The steps planned changed (a sweep point left out draws no timing steps).
    void set_total(int total) { total_ = total; }
    // Ends a line rewritten in place, so that what is printed next starts on a line of its own.
    void finish();
    double elapsed_seconds() const;

private:
    std::string task_;
    int total_;
    int done_ = 0;
    std::FILE* stream_;
    bool in_place_;          // a terminal: one line, rewritten
    bool line_open_ = false;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace gsv
