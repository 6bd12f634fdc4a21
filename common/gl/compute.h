#pragma once
// Compute dispatches over a 1D range of items (particles). One dimension of work groups is not enough for
// large ranges: GL guarantees only 65535 groups per dimension, and a dispatch past the limit does nothing
// but raise GL_INVALID_VALUE. So the groups are laid out over x and y, the shader turns (x, y) back into one
// index, and invocations past the item count do nothing (the bounds check): the last row of groups is
// usually not full.
#include "common/gl/gl_object.h"

#include <cstdint>

namespace gsv {

struct ComputeLimits {
    std::int64_t max_group_count[3] = {65535, 65535, 65535};  // GL_MAX_COMPUTE_WORK_GROUP_COUNT
    std::int64_t max_group_size[3] = {1024, 1024, 64};        // GL_MAX_COMPUTE_WORK_GROUP_SIZE
    std::int64_t max_invocations = 1024;                      // GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS
    std::int64_t max_storage_block_bytes = 1 << 27;           // GL_MAX_SHADER_STORAGE_BLOCK_SIZE
};
// The current context's limits; needs OpenGL 4.3 (throws gsv::UnsupportedError below it).
ComputeLimits compute_limits();

struct DispatchGrid {
    std::uint32_t groups_x = 0, groups_y = 0;
    std::uint64_t invocations(std::uint32_t local_size) const {
        return std::uint64_t(groups_x) * groups_y * local_size;
    }
};
// The smallest near-square split: groups_y rows of groups_x groups, each row within the x limit. Throws
// gsv::UnsupportedError naming the numbers when even that exceeds the y limit, and gsv::Error for a local
// size of 0. No items: no groups.
DispatchGrid dispatch_grid(std::uint64_t items, std::uint32_t local_size, const ComputeLimits& limits);

// Runs the bound compute program over `items` items with dispatch_grid's layout and checks the GL error,
// so a refused dispatch is an error with the numbers instead of a silent no-op.
void dispatch_items(std::uint64_t items, std::uint32_t local_size, const ComputeLimits& limits);

}  // namespace gsv
