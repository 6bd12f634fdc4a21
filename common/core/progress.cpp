#include "common/core/progress.h"

#include <algorithm>
#include <cmath>
#include <utility>

#ifdef _WIN32
#include <io.h>
#define gsv_isatty _isatty
#define gsv_fileno _fileno
#else
#include <sys/ioctl.h>
#include <unistd.h>
#define gsv_isatty isatty
#define gsv_fileno fileno
#endif

namespace gsv {
namespace {

// The terminal's width: a rewritten line must not wrap, or the carriage return goes back to its last row only.
std::size_t terminal_columns(std::FILE* stream) {
#ifndef _WIN32
    winsize size{};
    if (ioctl(gsv_fileno(stream), TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
#else
    (void)stream;
#endif
    return 80;
}

}  // namespace

std::string duration_text(double seconds) {
    const long s = std::lround(std::max(0.0, seconds));
    char text[48];
    if (s < 60) std::snprintf(text, sizeof text, "%ld s", s);
    else if (s < 3600) std::snprintf(text, sizeof text, "%ld min %ld s", s / 60, s % 60);
    else std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
    return text;
}

std::string progress_text(int done, int total, const std::string& what, double elapsed_seconds) {
    std::string text = "[" + std::to_string(done) + "/" + std::to_string(total) + "] " + what;
    if (done >= total) return text + ", done in " + duration_text(elapsed_seconds);
    if (done > 0) text += ", about " + duration_text(elapsed_seconds / done * (total - done)) + " left";
    return text;
}

Progress::Progress(std::string task, int total, std::FILE* stream)
    : task_(std::move(task)), total_(total), stream_(stream), in_place_(gsv_isatty(gsv_fileno(stream)) != 0),
      start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() { finish(); }

double Progress::elapsed_seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::step(const std::string& what) {
    ++done_;
    std::string line = task_ + " " + progress_text(done_, total_, what, elapsed_seconds());
    if (in_place_) {
        // The estimate is at the end; the step's name in the middle gives way.
        const std::size_t columns = terminal_columns(stream_) - 1;
        if (line.size() > columns && columns > 40) {
            const std::size_t keep_end = columns / 2;
            line = line.substr(0, columns - keep_end - 3) + "..." + line.substr(line.size() - keep_end);
        }
        // Carriage return, the line, then erase what a longer previous line left to its right.
        std::fprintf(stream_, "\r%s\033[K", line.c_str());
        line_open_ = true;
    } else {
        std::fprintf(stream_, "%s\n", line.c_str());
    }
    std::fflush(stream_);
}

void Progress::finish() {
    if (!line_open_) return;
    std::fprintf(stream_, "\n");
    std::fflush(stream_);
    line_open_ = false;
}

}  // namespace gsv
