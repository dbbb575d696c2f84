// GL timestamps (ARB_timer_query's glQueryCounter) from one pool of queries, each read back once
// the GPU has reached it, never waited for: what the auto geometry's calibration and the tiles'
// timeline time the GPU with (gpu_timestamps() says where they time it).
#pragma once
#include <vector>

#include "gl/caps.h"
#include "gl/gl.h"

namespace dsr {

// Whether GL timestamps (ARB_timer_query's glQueryCounter) time the GPU's work on this GL: there
// is the counter, and the GL is not a CPU rasteriser, whose queries do not time its rasterisation
// (the auto geometry's calibration, the tiles' timeline).
bool gpu_timestamps(const Caps& caps);

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
