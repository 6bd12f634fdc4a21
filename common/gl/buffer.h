#pragma once
// GPU buffers: vertex, index, uniform and shader-storage. Storage buffers are filled the way the
// particle lab teaches: allocate with no data, map with GL_MAP_INVALIDATE_BUFFER_BIT, write, unmap.
#include "common/gl/gl_object.h"

#include <cstddef>

namespace gsv {

class Buffer {
public:
    Buffer() = default;
    // `data` may be null to allocate without contents.
    static Buffer create(GLenum target, std::size_t bytes, const void* data, GLenum usage = GL_STATIC_DRAW);

    void bind() const { glBindBuffer(target_, name_.get()); }
    // Binds to an indexed point (uniform or shader-storage binding `index`).
    void bind_base(GLuint index) const;
    void upload(std::size_t offset, std::size_t bytes, const void* data);

    // Maps the whole buffer for writing, discarding its old contents so the driver need not wait for
    // the GPU to finish with them. Pair with unmap(); throws if the driver refuses the mapping.
    void* map_write_invalidate();
    void* map_read();
    void unmap();

    template <class T> T* map_write_invalidate_as() { return static_cast<T*>(map_write_invalidate()); }
    template <class T> const T* map_read_as() { return static_cast<const T*>(map_read()); }

    GLuint id() const { return name_.get(); }
    GLenum target() const { return target_; }
    std::size_t size() const { return size_; }

private:
    BufferName name_;
    GLenum target_ = GL_ARRAY_BUFFER;
    std::size_t size_ = 0;
};

}  // namespace gsv
