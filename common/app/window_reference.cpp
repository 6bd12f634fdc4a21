#include "common/app/window_reference.h"

#include "common/app/reference_image.h"
#include "common/app/subprocess.h"
#include "common/core/error.h"
#include "common/image/comparison_image.h"
#include "common/image/image.h"

#include <chrono>
#include <cstdio>

namespace gsv {
namespace fs = std::filesystem;

PictureView next_view(PictureView view) {
    switch (view) {
    case PictureView::Yours: return PictureView::Reference;
    case PictureView::Reference: return PictureView::Split;
    case PictureView::Split: return PictureView::Difference;
    case PictureView::Difference: return PictureView::Yours;
    }
    return PictureView::Yours;
}

LiveReference::~LiveReference() {
    if (job_.valid()) job_.wait();  // before the folder it writes into goes
}

const Image* LiveReference::get(Session& s, int width, int height) {
    ReferenceSource source;
    try {
        source = find_reference(s);
    } catch (const Error& e) {
        status_ = e.what();
        return nullptr;
    }
    if (source.kind == ReferenceSource::Kind::Golden) {
        const std::string key = source.path.string();
        if (ready_key_ != key) {
            image_ = read_png(source.path);
            ready_key_ = key;
        }
        status_ = source.describe(s);
        return &*image_;
    }
    // The settings as the solution's command line: the same line twice is the same picture.
    std::string key;
    for (const auto& arg : reference_render_arguments(s, folder_.path() / "reference.png", width, height)) key += arg + '\n';
    if (job_.valid() && job_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
        try {
            image_ = job_.get();
            ready_key_ = running_key_;
        } catch (const Error& e) {
            failed_key_ = running_key_;
            status_ = e.what();
        }
    }
    if (key != ready_key_ && key != failed_key_ && !job_.valid()) {
        const fs::path png = folder_.path() / ("reference-" + std::to_string(renders_++) + ".png");
        std::vector<std::string> argv{source.path.string()};
        for (const auto& arg : reference_render_arguments(s, png, width, height)) argv.push_back(arg);
        const fs::path log = fs::path(png).replace_extension(".log");
        running_key_ = key;
        job_ = std::async(std::launch::async, [argv, png, log] {
            const ProgramExit exit = run_program(argv, log);
            if (!exit.ok()) throw Error("the reference " + argv[0] + " failed (its output: " + log.string() + ")");
            Image image = read_png(png);
            std::error_code ec;
            fs::remove(png, ec);
            return image;
        });
    }
    if (key == ready_key_ && image_) {
        status_ = source.describe(s);
        return &*image_;
    }
    if (key == failed_key_) return nullptr;
    status_ = "rendering the reference with " + source.path.filename().string() + " ...";
    return nullptr;
}

ComposedView compose_view(PictureView view, const Image& yours, const Image& reference, const std::string& source) {
    if (view == PictureView::Reference) return {reference, "the reference: " + source};
    if (yours.width != reference.width || yours.height != reference.height)
        return {reference, "the reference (" + std::to_string(reference.width) + "x" + std::to_string(reference.height) +
                               ", yours " + std::to_string(yours.width) + "x" + std::to_string(yours.height) +
                               ": give the window --size " + std::to_string(reference.width) + "x" +
                               std::to_string(reference.height) + " to compare): " + source};
    if (view == PictureView::Split) {
        Image split = yours;
        const int middle = yours.width / 2;
        for (int y = 0; y < yours.height; ++y)
            for (int x = middle; x < yours.width; ++x) {
                const std::uint8_t* from = reference.at(x, y);
                std::uint8_t* to = split.at(x, y);
                const bool divider = x < middle + 2;
                for (int c = 0; c < 4; ++c) to[c] = divider ? 255 : from[c];
            }
        return {split, "left: yours, right: the reference (" + source + ")"};
    }
    const ImageDifference difference = image_difference(yours, reference);
    const int factor = difference_factor(difference.max_rgb);
    char numbers[160];
    std::snprintf(numbers, sizeof numbers, "|yours - reference| x%d: largest %d levels, RMSE %.2f, %ld pixels differ", factor,
                  difference.max_rgb, difference.rmse, difference.differing_pixels);
    return {amplified_difference(yours, reference, factor), numbers};
}

}  // namespace gsv
