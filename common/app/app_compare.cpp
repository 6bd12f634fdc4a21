// Compare mode: this binary's render beside the reference's (the solution rendering the same settings now, or the
// case's golden image) and their difference, amplified, in one PNG, with RMSE and the largest difference printed.
// What a student looks at before asking why a case fails, and what a lecturer projects.
#include "common/app/app_session.h"
#include "common/app/known_mistake_pictures.h"
#include "common/app/reference_image.h"
#include "common/core/error.h"
#include "common/gl/framebuffer.h"
#include "common/gl/gl.h"
#include "common/image/comparison_image.h"
#include "common/io/output_folder.h"

#include <cstdio>
#include <optional>
#include <string>

namespace gsv {

int run_compare(Session& s) {
    std::string png = s.options.out;
    if (png.empty()) png = s.info.id + "-compare" + (s.options.case_name.empty() ? "" : "-" + s.options.case_name) + ".png";
    prepare_output_file(png, "--out");
    const ReferenceSource source = find_reference(s);
    Image golden;
    if (source.kind == ReferenceSource::Kind::Golden) {
        golden = reference_image(s, source, 0, 0);
        const std::string golden_size = std::to_string(golden.width) + "x" + std::to_string(golden.height);
        if (s.options.size_given && (s.options.width != golden.width || s.options.height != golden.height))
            throw Error("--size " + std::to_string(s.options.width) + "x" + std::to_string(s.options.height) +
                        " differs from the golden image's " + golden_size + " (" + source.path.string() +
                        "); leave --size out to compare at the golden's size");
        s.options.width = golden.width;
        s.options.height = golden.height;
    }
    const int width = s.options.width, height = s.options.height;

    s.open(s.headless_backend());
    if (auto error = s.sync_params()) throw Error(*error);
    Framebuffer target = frame_target(s, width, height);
    target.bind();
    s.render_frame(Frame{width, height, 0.0});
    check_gl_error("rendering the frame");
    const Readback yours = read_back(target);

    const Image reference = source.kind == ReferenceSource::Kind::Golden ? golden : reference_image(s, source, width, height);
    const std::string reference_text = source.describe(s);
    // A fourth view where the case is named and yours is the picture of a mistake the kit knows (the pictures it ships).
    std::optional<MistakePanel> mistake;
    if (!s.options.case_name.empty()) {
        KnownMistakePictures known;
        try {
            known = read_known_mistake_pictures(s.find_assets().layout().root, s.info.id);
        } catch (const Error& e) {
            std::fprintf(stderr, "%s: the known mistakes are left out of the comparison: %s\n", s.info.id.c_str(), e.what());
        }
        mistake = known_mistake_panel(known, s.options.case_name, yours.image, reference);
    }
    const Image composite = compose_comparison(yours.image, reference, "yours: " + s.title(), "reference: " + reference_text,
                                               nullptr, mistake ? &*mistake : nullptr);
    const ImageDifference d = image_difference(yours.image, reference);

    write_png(png, composite);
    std::printf("%s: wrote %s (yours | reference | difference x%d%s, %dx%d each)\n", s.info.id.c_str(), png.c_str(),
                difference_factor(d.max_rgb), mistake ? " | a known mistake's picture" : "", width, height);
    if (mistake) std::printf("%s: what went wrong: %s\n", s.info.id.c_str(), mistake->label.c_str());
    std::printf("%s: against %s: RMSE %.4g, max difference %d of 255 (RGB), %ld of %ld pixels differ\n",
                s.info.id.c_str(), reference_text.c_str(), d.rmse, d.max_rgb, d.differing_pixels,
                static_cast<long>(width) * height);
    if (yours.non_finite()) {
        std::fprintf(stderr, "%s: your image has %ld NaN and %ld Inf pixel values (painted magenta in %s)\n",
                     s.info.id.c_str(), yours.stats.nan_count, yours.stats.inf_count, png.c_str());
        return kExitNonFinite;
    }
    return kExitOk;
}

}  // namespace gsv
