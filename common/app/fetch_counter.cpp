#include "common/app/fetch_counter.h"

#include "common/core/error.h"
#include "common/gl/gl.h"

#include <cstdlib>
#include <string>

namespace gsv {

std::optional<ShaderDefine> fetch_count_define() {
    const char* value = std::getenv("GSV_COUNT_FETCHES");
    if (!value || !*value) return std::nullopt;
    if (std::string(value) != "1")
        throw Error(std::string("GSV_COUNT_FETCHES=") + value + ": set it to 1 to count texture fetches, or unset it");
    return ShaderDefine{"GSV_COUNT_FETCHES", "1"};
}

FetchCounter::FetchCounter() {
    if (gl_is_es() || !GLAD_GL_VERSION_4_2)
        throw UnsupportedError("counting texture fetches (GSV_COUNT_FETCHES) needs atomic counters: OpenGL 4.2 (--gl 4.5)");
    const std::uint32_t zeros[3] = {0, 0, 0};
    buffer_ = Buffer::create(GL_ATOMIC_COUNTER_BUFFER, sizeof zeros, zeros, GL_DYNAMIC_READ);
    GLuint query = 0;
    glGenQueries(1, &query);
    primitives_ = QueryName(query);
}

void FetchCounter::reset_and_bind() {
    const std::uint32_t zeros[3] = {0, 0, 0};
    buffer_.upload(0, sizeof zeros, zeros);
    buffer_.bind_base(0);
    glBeginQuery(GL_PRIMITIVES_GENERATED, primitives_.get());
}

FetchCounts FetchCounter::read() {
    glEndQuery(GL_PRIMITIVES_GENERATED);
    glMemoryBarrier(GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    glFinish();
    std::uint32_t counts[3] = {0, 0, 0};
    buffer_.bind();
    glGetBufferSubData(GL_ATOMIC_COUNTER_BUFFER, 0, sizeof counts, counts);
    GLuint64 primitives = 0;
    glGetQueryObjectui64v(primitives_.get(), GL_QUERY_RESULT, &primitives);
    check_gl_error("reading the texture fetch counters");
    return {counts[0], counts[1], counts[2], primitives};
}

}  // namespace gsv
