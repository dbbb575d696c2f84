#include "gl/rounding_probe.h"

#include <algorithm>
#include <cstdio>

#include "gl/caps.h"
#include "gl/pbuffer.h"
#include "gl/state.h"

namespace dsr {

namespace {

// Fills the bound 4x4 target with colour (v, v, v, 1) / 255 by a fixed-function quad; returns
// the red bytes.
void fill(float v) {
    glColor4f(v / 255.0f, v / 255.0f, v / 255.0f, 1.0f);
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();
}

void read_red(unsigned char out[16]) {
    unsigned char px[64];
    glReadPixels(0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, px);
    for (int i = 0; i < 16; ++i) out[i] = px[4 * i];
}

}  // namespace

Unorm8Rounding probe_unorm8_rounding() {
    Unorm8Rounding r;
    if (!has_extension("GL_EXT_framebuffer_object")) return r;
    PBufferDesc d;
    d.width = d.height = 4;
    d.color_formats = {GL_RGBA8};
    PBuffer target("rounding probe", d);
    target.bind_render();
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
    RenderState s;  // fixed function, no blending, dither off
    gl_state().reset();
    gl_state().apply(s);
    unsigned char px[16];
    const float values[4] = {0.4f, 0.6f, 1.5f, 2.5f};
    for (int i = 0; i < 4; ++i) {
        fill(values[i]);
        read_red(px);
        r.plain[i] = px[0];
    }
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    RenderState add = s;
    add.blend = true;
    add.blend_src = add.blend_dst = GL_ONE;
    gl_state().apply(add);
    for (int k = 0; k < 10; ++k) fill(0.6f);
    read_red(px);
    r.added_ten = px[0];
    RenderState dither = s;
    dither.dither = true;
    gl_state().apply(dither);
    fill(1.5f);
    read_red(px);
    r.dither_min = *std::min_element(px, px + 16);
    r.dither_max = *std::max_element(px, px + 16);
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glPopMatrix();
    glColor4f(1, 1, 1, 1);
    target.unbind_render();
    gl_state().reset();
    r.measured = true;
    return r;
}

std::string describe(const Unorm8Rounding& r) {
    if (!r.measured) return "  RGBA8 rounding  not measured (no framebuffer objects)\n";
    char b[320];
    std::snprintf(b, sizeof b,
                  "  RGBA8 rounding  v/255 written: 0.4 -> %d, 0.6 -> %d, 1.5 -> %d, 2.5 -> %d; 10 x 0.6/255 added -> %d; "
                  "1.5/255 with GL_DITHER on over 4x4: %d..%d\n",
                  r.plain[0], r.plain[1], r.plain[2], r.plain[3], r.added_ten, r.dither_min, r.dither_max);
    return b;
}

}  // namespace dsr
