// A vertex buffer object refilled every frame (GL 1.5's buffer objects, GL_STREAM_DRAW): where a
// pass builds its vertices on the CPU each frame (the tiles geometry's quads), one upload per frame
// instead of client arrays re-read by the driver at every draw. RAII; needs a current context.
#pragma once
#include <cstddef>

#include "gl/gl.h"

namespace dsr {

class StreamBuffer {
public:
    StreamBuffer() = default;
    ~StreamBuffer();
    StreamBuffer(const StreamBuffer&) = delete;
    StreamBuffer& operator=(const StreamBuffer&) = delete;

    // Replaces the contents with `bytes` bytes from `data` (a fresh store: the driver need not
    // wait for draws still reading the old one) and leaves the buffer bound to GL_ARRAY_BUFFER.
    void upload(const void* data, size_t bytes);
    // Unbinds GL_ARRAY_BUFFER, so that later client-array draws read client memory again.
    static void unbind();

private:
    GLuint id_ = 0;
};

}  // namespace dsr
