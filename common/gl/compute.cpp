#include "common/gl/compute.h"

#include "common/core/error.h"
#include "common/gl/gl.h"

#include <string>

namespace gsv {

ComputeLimits compute_limits() {
    if (!(gl_is_es() ? GLAD_GL_ES_VERSION_3_1 : GLAD_GL_VERSION_4_3)) throw UnsupportedError("compute shaders need OpenGL 4.3 or OpenGL ES 3.1");
    ComputeLimits l;
    for (GLuint axis = 0; axis < 3; ++axis) {
        GLint value = 0;
        glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, axis, &value);
        l.max_group_count[axis] = value;
        glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_SIZE, axis, &value);
        l.max_group_size[axis] = value;
    }
    GLint value = 0;
    glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &value);
    l.max_invocations = value;
    GLint64 bytes = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &bytes);
    l.max_storage_block_bytes = bytes;
    check_gl_error("reading the compute limits");
    return l;
}

DispatchGrid dispatch_grid(std::uint64_t items, std::uint32_t local_size, const ComputeLimits& limits) {
    if (local_size == 0) throw Error("a compute dispatch needs a local size of at least 1");
    const std::uint64_t groups = (items + local_size - 1) / local_size;
    if (groups == 0) return {};
    const auto max_x = static_cast<std::uint64_t>(limits.max_group_count[0]);
    const auto max_y = static_cast<std::uint64_t>(limits.max_group_count[1]);
    const std::uint64_t rows = (groups + max_x - 1) / max_x;
    if (rows > max_y)
        throw UnsupportedError(std::to_string(items) + " items in groups of " + std::to_string(local_size) + " need " +
                               std::to_string(groups) + " work groups, over this GPU's " + std::to_string(max_x) +
                               " x " + std::to_string(max_y));
    // Equal rows rather than full rows and a stub: fewer idle invocations in the last row.
    const std::uint64_t columns = (groups + rows - 1) / rows;
    return {static_cast<std::uint32_t>(columns), static_cast<std::uint32_t>(rows)};
}

void dispatch_items(std::uint64_t items, std::uint32_t local_size, const ComputeLimits& limits) {
    const DispatchGrid grid = dispatch_grid(items, local_size, limits);
    if (grid.groups_x == 0) return;
    glDispatchCompute(grid.groups_x, grid.groups_y, 1);
    const GLenum error = glGetError();
    if (error != GL_NO_ERROR)
        throw Error("glDispatchCompute(" + std::to_string(grid.groups_x) + ", " + std::to_string(grid.groups_y) +
                    ", 1) for " + std::to_string(items) + " items failed: " + gl_error_name(error));
}

}  // namespace gsv
