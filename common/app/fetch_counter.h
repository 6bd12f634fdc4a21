#pragma once
// The instrumented build that counts a lab's texture fetches (shaders/gsv/fetch_count.glsl) and the primitives its
// draws send (a GL_PRIMITIVES_GENERATED query: every triangle assembled, culled or drawn): independent counts to hold
// a lab's stated work (Lab::frame_work) against. GSV_COUNT_FETCHES=1 in the environment compiles every lab shader
// with the counting lookups; render mode then draws one more frame with the counter bound and reports both.
#include "common/gl/buffer.h"
#include "common/gl/gl_object.h"
#include "common/shader/shader_source.h"

#include <cstdint>
#include <optional>

namespace gsv {

// None when GSV_COUNT_FETCHES is unset or empty; throws gsv::Error, one line, on a value other than 1.
std::optional<ShaderDefine> fetch_count_define();

struct FetchCounts {
    std::uint64_t texture_2d = 0, texture_3d = 0, texture_2d_array = 0;
    std::uint64_t primitives = 0;  // points, lines or triangles the draws sent, culled or not
};

// The counters at binding 0 of GL_ATOMIC_COUNTER_BUFFER, as fetch_count.glsl declares them, and the primitives query.
class FetchCounter {
public:
    FetchCounter();
    void reset_and_bind();  // and begins the query: read() ends it, after the frame
    FetchCounts read();     // waits for the draws that counted

private:
    Buffer buffer_;
    QueryName primitives_;
};

}  // namespace gsv
