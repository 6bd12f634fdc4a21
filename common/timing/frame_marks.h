#pragma once
// The grader's clock. A student's process cannot be trusted to report its own frame times, so under the grader
// each timed frame's end (after glFinish) is announced by one byte on a pipe the grader hands over as the file
// descriptor named in $GSV_FRAME_MARKS_FD, and the grader times the frames by when the bytes arrive. Outside the
// grader (no such variable) marking does nothing.
namespace gsv {

class FrameMarks {
public:
    FrameMarks();  // reads $GSV_FRAME_MARKS_FD
    void mark() const;
    bool active() const { return fd_ >= 0; }

private:
    int fd_ = -1;
};

}  // namespace gsv
