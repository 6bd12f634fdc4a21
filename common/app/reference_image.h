#pragma once
// The reference picture of a lab's current settings, for `labXX compare` and a live side-by-side view: the
// sibling <lab>_solution binary beside this executable, rendering the same parameters headless now (the
// instructor's kit), or else the case's committed golden image (a student's copy of the kit has no solutions).
#include "common/app/app_session.h"
#include "common/image/image.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

struct ReferenceSource {
    enum class Kind { Solution, Golden };
    Kind kind = Kind::Solution;
    std::filesystem::path path;  // the solution binary, or the golden PNG
    std::string case_name;       // the golden's case

    // For labels and messages: "lab01_solution, rendered now" or "golden image grader/golden/lab01/phong.png".
    std::string describe(const Session& session) const;
};

// The solution binary where there is one beside this executable and it is not this executable; else the golden
// image of the session's case. Throws gsv::Error, one line, when neither will do: no case to take a golden of, a
// case without a golden (a demo), or settings changed from the case's (--set, or in a window), which its golden
// does not show.
ReferenceSource find_reference(Session& session);

// The command line that makes the solution render what the session shows: the case, the --set assignments as typed,
// then every parameter that differs from those (changed in a window), and the profile and GL version.
std::vector<std::string> reference_render_arguments(Session& session, const std::filesystem::path& png, int width,
                                                    int height);

// The reference's image: rendered by the solution at width x height, or the golden image at its own size. Throws
// gsv::Error naming the solution and its last line of output when it fails.
Image reference_image(Session& session, const ReferenceSource& source, int width, int height);

}  // namespace gsv
