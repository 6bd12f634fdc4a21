#include "support/flow/lic_work.h"

#include <string>

namespace gsv {

FrameWork lic_work(const LicLoops& l) {
    const double pixels = static_cast<double>(l.width) * l.height;
    const double steps = static_cast<double>(l.directions) * l.length;
    const std::string L = "L = " + std::to_string(l.length);
    const std::string ways = l.directions == 2 ? "both ways" : "forward only";
    FrameWork work;
    work.upper_bound = true;
    work.items.push_back({WorkKind::Fetch, ShaderPath::Fragment, l.input_texture, pixels * (1 + steps),
                          "input: 1 + " + std::to_string(l.directions) + "L a pixel (" + ways + ", " + L + ")"});
    const int per_step = l.flow_reads_per_step * l.flow_fetches_per_read;
    if (l.length > 0)
        work.items.push_back({WorkKind::Fetch, ShaderPath::Fragment, l.flow_texture, pixels * steps * per_step,
                              "flow: " + std::to_string(l.directions * per_step) + "L a pixel (" +
                                  (l.flow_reads_per_step == 2 ? "midpoint" : "Euler") +
                                  (l.flow_fetches_per_read > 1 ? ", " + std::to_string(l.flow_fetches_per_read) + " lookups a read" : std::string()) +
                                  ", " + L + ")"});
    return work;
}

}  // namespace gsv
