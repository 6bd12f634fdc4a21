#include "common/timing/work_pacer.h"

#include <algorithm>
#include <cmath>

namespace gsv {

long WorkPacer::steps(long wanted, double cost, long most, double now) {
    const double unit = std::max(cost, 1e-9);
    if (unit != last_cost_) {
        one_step_s_.reset();
        last_cost_ = unit;
    }
    if (measuring_ && last_work_ > 0 && now > last_now_) {
        const double gap = now - last_now_;
        if (last_work_ == unit) one_step_s_ = one_step_s_ ? 0.5 * *one_step_s_ + 0.5 * gap : gap;
        const double target = std::max(target_s_, one_step_s_ ? 2 * *one_step_s_ : 0.0);
        budget_ = std::min(last_work_ * target / gap, 2 * last_work_);
    }
    const long affordable = static_cast<long>(std::floor(budget_ / unit));
    const long taken = std::max(1L, std::min({wanted, most, affordable}));
    last_now_ = now;
    last_work_ = static_cast<double>(taken) * unit;
    return taken;
}

}  // namespace gsv
