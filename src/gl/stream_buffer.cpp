#include "gl/stream_buffer.h"

#include "gl/entry_points.h"

namespace dsr {

StreamBuffer::~StreamBuffer() {
    if (id_) glDeleteBuffers(1, &id_);
}

void StreamBuffer::upload(const void* data, size_t bytes) {
    if (!id_) glGenBuffers(1, &id_);
    glBindBuffer(GL_ARRAY_BUFFER, id_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(bytes), data, GL_STREAM_DRAW);
}

void StreamBuffer::unbind() { glBindBuffer(GL_ARRAY_BUFFER, 0); }

void StreamBuffers::upload_next(const void* data, size_t bytes) {
    if (next_ == buffers_.size()) buffers_.push_back(std::make_unique<StreamBuffer>());
    buffers_[next_++]->upload(data, bytes);
}

}  // namespace dsr
