// GL timestamps (ARB_timer_query's glQueryCounter) from one pool of queries, each read back once
// the GPU has reached it, never waited for: what the auto geometry's calibration and the tiles'
// timeline time the GPU with (gpu_timestamps() in gl/frame_timer.h says where they time it).
#pragma once
#include <vector>

#include "gl/gl.h"

namespace dsr {

class GpuStamps {
public:
    GpuStamps() = default;
    GpuStamps(const GpuStamps&) = delete;
    GpuStamps& operator=(const GpuStamps&) = delete;
    ~GpuStamps();

    // A stamp issued now, from the pool: the GPU writes its clock when it reaches this point of
    // the command stream.
    GLuint stamp();
    // Whether the GPU has reached stamp q, so that ms(q) does not wait.
    static bool ready(GLuint q);
    // Stamp q's clock in milliseconds.
    static double ms(GLuint q);
    // q back to the pool, read or not (a later stamp() issues it again, replacing its result).
    void release(GLuint q) { free_.push_back(q); }

private:
    std::vector<GLuint> all_, free_;
};

}  // namespace dsr
