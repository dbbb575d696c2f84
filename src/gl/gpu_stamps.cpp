// GL timestamps from a pool (gpu_stamps.h).
#include "gl/gpu_stamps.h"

#include "gl/entry_points.h"

namespace dsr {

bool gpu_timestamps(const Caps& caps) {
    return caps.timer_query && gl_entry.QueryCounter && gl_entry.GetQueryObjectui64v && !caps.software_rasterizer;
}

GpuStamps::~GpuStamps() {
    if (!all_.empty()) glDeleteQueries(GLsizei(all_.size()), all_.data());
}

GLuint GpuStamps::stamp() {
    if (free_.empty()) {
        all_.push_back(0);
        glGenQueries(1, &all_.back());
        free_.push_back(all_.back());
    }
    const GLuint q = free_.back();
    free_.pop_back();
    glQueryCounter(q, GL_TIMESTAMP);
    return q;
}

bool GpuStamps::ready(GLuint q) {
    GLuint done = 0;
    glGetQueryObjectuiv(q, GL_QUERY_RESULT_AVAILABLE, &done);
    return done != 0;
}

double GpuStamps::ms(GLuint q) {
    GLuint64 ns = 0;
    glGetQueryObjectui64v(q, GL_QUERY_RESULT, &ns);
    return double(ns) * 1e-6;
}

}  // namespace dsr
