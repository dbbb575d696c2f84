// The counters around the light-shader draws (docs/benchmarks.md reads them): an occlusion query
// (light_fragments: samples that passed) and a pipeline-statistics query (light_invocations:
// fragments that entered the light shader) per draw, read after the last draw so no light waits
// on the one before it. Each draw's invocations times the lights each of its fragments evaluates
// give light_evaluations, the pixel-light pairs the passes paid for: one light a fragment for a
// light's own pass, a batch's every light for a full-screen batch, a tile's list for the tiles.
// Only the light shader's draws are counted, never a stencil pass. Whether a frame counts at all
// is decided once, by the lighting stage (LightingStage::draw_lighting).
#pragma once
#include <cmath>
#include <vector>

#include "deferred/frame_stats.h"
#include "gl/gl.h"

namespace dsr {

class LightQueries {
public:
    LightQueries(bool samples, bool invocations) : samples_(samples), invocations_(invocations) {}
    LightQueries(const LightQueries&) = delete;
    LightQueries& operator=(const LightQueries&) = delete;
    ~LightQueries() {
        if (!q_.empty()) glDeleteQueries(GLsizei(q_.size()), q_.data());
        if (!inv_.empty()) glDeleteQueries(GLsizei(inv_.size()), inv_.data());
    }
    // Around one draw of the light shader whose every fragment evaluates `lights` lights (a tile
    // draw of lists of different lengths: their mean over the draw's pixels).
    void begin(double lights = 1.0) {
        if (samples_) {
            q_.push_back(0);
            glGenQueries(1, &q_.back());
            glBeginQuery(GL_SAMPLES_PASSED, q_.back());
        }
        if (invocations_) {
            inv_.push_back(0);
            lights_.push_back(lights);
            glGenQueries(1, &inv_.back());
            glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, inv_.back());
        }
    }
    void end() {
        if (invocations_) glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
        if (samples_) glEndQuery(GL_SAMPLES_PASSED);
    }
    // Sums the results into the frame's light counts (fragments; invocations and evaluations where
    // counted): the only part of the frame's stats the queries measure.
    void collect(LightCounts& counts) {
        counts.fragments_counted = samples_;
        for (GLuint q : q_) {
            GLuint n = 0;
            glGetQueryObjectuiv(q, GL_QUERY_RESULT, &n);
            counts.fragments += n;
        }
        if (invocations_) {
            long long total = 0;
            double evaluations = 0;
            for (size_t i = 0; i < inv_.size(); ++i) {
                GLuint n = 0;  // one draw: at most w x h fragments, fits 32 bits
                glGetQueryObjectuiv(inv_[i], GL_QUERY_RESULT, &n);
                total += n;
                evaluations += double(n) * lights_[i];
            }
            counts.invocations = total;
            counts.evaluations = (long long)std::llround(evaluations);
        }
    }

private:
    bool samples_, invocations_;
    std::vector<GLuint> q_, inv_;
    std::vector<double> lights_;  // begin()'s `lights`, one per inv_
};

}  // namespace dsr
