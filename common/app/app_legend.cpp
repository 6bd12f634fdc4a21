// --legend: the lab's legend beside a headless image.
#include "common/app/app_session.h"
#include "common/core/error.h"
#include "common/gl/gl.h"
#include "common/image/legend_image.h"

namespace gsv {

Image with_lab_legend(Session& s, const Image& image) {
    const std::optional<Legend> legend = s.lab->legend(*s.kit);
    check_gl_error("sampling the legend's colours");
    if (!legend)
        throw Error("--legend: " + s.info.id + "'s colours stand for no value with these settings, so it has no legend "
                    "(labs 04 to 07 have one where colour is data)");
    return with_legend(image, *legend);
}

}  // namespace gsv
