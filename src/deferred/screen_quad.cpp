// Screen quads over a P-buffer's content (screen_quad.h).
#include "deferred/screen_quad.h"

#include <algorithm>
#include <vector>

#include "gl/state.h"
#include "gl/vertex_arrays.h"

namespace dsr {

namespace {

// OpenGL ES 2.0 has neither glBegin nor GL_QUADS (docs/gles2.md): quads (4 corners each, in
// order) as two triangles each, (0,1,2) and (0,2,3) as GL_QUADS splits them, from client memory
// through the prelude's attributes. `uv`: 2 floats a corner (gl_MultiTexCoord0); `ray`: 3 a
// corner (gl_MultiTexCoord1) or null.
void es_quads(const std::vector<float>& xy, const std::vector<float>& uv, const std::vector<float>& ray) {
    static const int corner[6] = {0, 1, 2, 0, 2, 3};
    std::vector<float> p, t, r;
    for (size_t q = 0; q < xy.size() / 8; ++q)
        for (int c : corner) {
            const size_t i = q * 4 + size_t(c);
            p.insert(p.end(), {xy[2 * i], xy[2 * i + 1]});
            t.insert(t.end(), {uv[2 * i], uv[2 * i + 1]});
            if (!ray.empty()) r.insert(r.end(), {ray[3 * i], ray[3 * i + 1], ray[3 * i + 2]});
        }
    vertex_array(2, 0, p.data());
    texcoord_array(0, 2, 0, t.data());
    if (!r.empty()) texcoord_array(1, 3, 0, r.data());
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(p.size() / 2));
    if (!r.empty()) disable_texcoord_array(1);
    disable_texcoord_array(0);
    disable_vertex_array();
}

}  // namespace

void draw_rect(const FrameDef& f, float x0, float y0, float x1, float y1, bool rays) {
    const float xs[4] = {x0, x1, x1, x0}, ys[4] = {y0, y0, y1, y1};
    const float sx = f.uv_scale.x, sy = f.uv_scale.y;  // into the G-buffer's (maybe padded) extent
    if (gl_state().es()) {
        std::vector<float> xy, uv, ray;
        for (int i = 0; i < 4; ++i) {
            xy.insert(xy.end(), {xs[i], ys[i]});
            uv.insert(uv.end(), {xs[i] * sx, ys[i] * sy});
            if (!rays) continue;
            const glm::vec3 r = f.view_ray_at(xs[i], ys[i]);
            ray.insert(ray.end(), {r.x, r.y, r.z});
        }
        return es_quads(xy, uv, ray);
    }
    glBegin(GL_QUADS);
    for (int i = 0; i < 4; ++i) {
        glMultiTexCoord2f(GL_TEXTURE0, xs[i] * sx, ys[i] * sy);
        if (rays) {
            // Bilinear in the screen's corner rays: exactly the corner's ray at a screen corner,
            // a tile's corner otherwise.
            const glm::vec3 r = f.view_ray_at(xs[i], ys[i]);
            glMultiTexCoord3f(GL_TEXTURE1, r.x, r.y, r.z);
        }
        glVertex2f(xs[i], ys[i]);
    }
    glEnd();
}

// [0,w]x[0,h] in the current ortho camera, texture coordinates 0..(sx,sy): the source's
// content extent (less than 1 when padded to powers of two).
void draw_quad(float w, float h, float sx, float sy) {
    if (gl_state().es()) return es_quads({0, 0, w, 0, w, h, 0, h}, {0, 0, sx, 0, sx, sy, 0, sy}, {});
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(0, 0);
    glTexCoord2f(sx, 0); glVertex2f(w, 0);
    glTexCoord2f(sx, sy); glVertex2f(w, h);
    glTexCoord2f(0, sy); glVertex2f(0, h);
    glEnd();
}

// [0,w]x[0,h] sampling buffer b's content bilinearly (fixed function) as CLAMP_TO_EDGE does
// on an unpadded texture. A padded (power-of-two) texture has no edge where the content ends:
// pixels whose sample point lies past the last texel centre would blend in a quarter texel of
// padding. Those pixels get a strip of their own whose coordinate is held at the last texel
// centre, so they read the edge texel alone, as the unpadded path does.
void draw_quad_clamped(float w, float h, const PBuffer& b) {
    const float tw = float(b.texture_width()), th = float(b.texture_height());
    const float cw = float(b.width()), ch = float(b.height());
    const float sx = cw / tw, sy = ch / th;
    if (tw == cw && th == ch) return draw_quad(w, h, sx, sy);
    // Screen splits where u reaches the last texel centre; none along an axis that is unpadded.
    const float xs[3] = {0, tw > cw ? w * (cw - 0.5f) / cw : w, w};
    const float ys[3] = {0, th > ch ? h * (ch - 0.5f) / ch : h, h};
    auto u = [&](float x) { return std::min(x / w * sx, (cw - 0.5f) / tw); };
    auto v = [&](float y) { return std::min(y / h * sy, (ch - 0.5f) / th); };
    if (gl_state().es()) {
        std::vector<float> xy, uv;
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
                const float x0 = xs[i], x1 = xs[i + 1], y0 = ys[j], y1 = ys[j + 1];
                if (x1 <= x0 || y1 <= y0) continue;
                xy.insert(xy.end(), {x0, y0, x1, y0, x1, y1, x0, y1});
                uv.insert(uv.end(), {u(x0), v(y0), u(x1), v(y0), u(x1), v(y1), u(x0), v(y1)});
            }
        return es_quads(xy, uv, {});
    }
    glBegin(GL_QUADS);
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            const float x0 = xs[i], x1 = xs[i + 1], y0 = ys[j], y1 = ys[j + 1];
            if (x1 <= x0 || y1 <= y0) continue;
            glTexCoord2f(u(x0), v(y0)); glVertex2f(x0, y0);
            glTexCoord2f(u(x1), v(y0)); glVertex2f(x1, y0);
            glTexCoord2f(u(x1), v(y1)); glVertex2f(x1, y1);
            glTexCoord2f(u(x0), v(y1)); glVertex2f(x0, y1);
        }
    glEnd();
}

// Texel centres of a buffer's content in texture coordinates: what CLAMP_TO_EDGE gives on
// an unpadded texture, so padded (power-of-two) buffers sample the same.
glm::vec4 uv_clamp(const PBuffer& b) {
    float tw = float(b.texture_width()), th = float(b.texture_height());
    return {0.5f / tw, 0.5f / th, (b.width() - 0.5f) / tw, (b.height() - 0.5f) / th};
}

}  // namespace dsr
