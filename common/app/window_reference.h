#pragma once
// The student's picture beside the reference's, live in the window (V steps through the views): the reference is
// rendered by the kit's solution in a child process with the window's current settings, so the window keeps
// drawing while it comes, or is the case's golden image where the kit has no solution.
#include "common/app/app_session.h"
#include "common/image/image.h"
#include "common/io/temporary_folder.h"

#include <filesystem>
#include <future>
#include <optional>
#include <string>

namespace gsv {

enum class PictureView { Yours, Reference, Split, Difference };
PictureView next_view(PictureView view);

class LiveReference {
public:
    LiveReference() = default;
    ~LiveReference();
    LiveReference(const LiveReference&) = delete;
    LiveReference& operator=(const LiveReference&) = delete;

    // The reference of the session's current settings at this size once it is ready; nullptr while it renders or
    // where there is none, and then status() says why.
    const Image* get(Session& session, int width, int height);
    const std::string& status() const { return status_; }
    bool pending() const { return job_.valid(); }

private:
    TemporaryFolder folder_{"gsv-live-reference-"};  // the solution's renders
    std::string ready_key_, running_key_, failed_key_;
    std::future<Image> job_;
    std::optional<Image> image_;
    std::string status_;
    int renders_ = 0;
};

// What the view shows, and a line saying what it is: the reference as it is; yours on the left half and the
// reference on the right; or their difference, amplified, with the factor and the numbers.
struct ComposedView {
    Image image;
    std::string caption;
};
ComposedView compose_view(PictureView view, const Image& yours, const Image& reference, const std::string& source);

}  // namespace gsv
