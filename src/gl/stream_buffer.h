// A vertex buffer object refilled every frame (GL 1.5's buffer objects, GL_STREAM_DRAW): where a
// pass builds its vertices on the CPU each frame (the tiles geometry's quads), one upload per frame
// instead of client arrays re-read by the driver at every draw. RAII; needs a current context.
#pragma once
#include <cstddef>
#include <memory>
#include <vector>

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

// A frame's batches each in a StreamBuffer of its own, kept between frames: refilling the buffer
// that the previous batch's draws still read makes llvmpipe finish them first, stalling the plan
// of the next batch (docs/tiles.md, "The plan").
class StreamBuffers {
public:
    // Before the frame's first upload.
    void begin_frame() { next_ = 0; }
    // The frame's next buffer, filled with `bytes` bytes from `data` and left bound to GL_ARRAY_BUFFER.
    void upload_next(const void* data, size_t bytes);

private:
    std::vector<std::unique_ptr<StreamBuffer>> buffers_;
    size_t next_ = 0;  // this frame's uploads so far
};

}  // namespace dsr
