#include "common/timing/frame_marks.h"

#include "common/core/number_text.h"

#include <cstdlib>
#include <string>

#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#endif

namespace gsv {

FrameMarks::FrameMarks() {
#if defined(__unix__) || defined(__APPLE__)
    if (const char* text = std::getenv("GSV_FRAME_MARKS_FD"); text && *text)
        if (const auto fd = parse_finite_number(text); fd && *fd >= 3 && *fd < 1024 && *fd == static_cast<int>(*fd))
            fd_ = static_cast<int>(*fd);
#endif
}

void FrameMarks::mark() const {
#if defined(__unix__) || defined(__APPLE__)
    if (fd_ >= 0) (void)!write(fd_, "f", 1);
#endif
}

}  // namespace gsv
