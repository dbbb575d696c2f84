// A shadow map without framebuffer objects: drawn into the main frame buffer (framebuffer 0, the
// current drawable) and copied into its texture with glCopyTexSubImage2D, the copy P-buffers' way
// (gl/pbuffer.h) and the pre-FBO shadow maps'. The shadow stage runs before the geometry stage,
// which clears the whole drawable's depth and colour before it draws (and the pbuffer
// implementation draws every buffer on a surface of its own), so nothing of the frame is lost.
#pragma once
#include <functional>
#include <vector>

#include "deferred/map_pieces.h"
#include "gl/caps.h"
#include "gl/gl.h"

namespace dsr {

// The main frame buffer's depth bits (GL_DEPTH_BITS of framebuffer 0, which must be bound).
int main_buffer_depth_bits();

// Whether this GL's shadow maps are packed in RGB8 (maps_packed): without framebuffer objects it
// asks the current drawable for its depth bits. The one answer for the shadow stage and for the
// programs (shader_table.cpp: the caster's and the lookups' SHADOW_PACKED).
bool shadow_maps_packed(const Caps& caps);

// Draws `texture`'s image piece by piece (map_pieces): for each, the scissor at the piece's size
// at the lower left, `clear`, draw(piece), which draws with its viewports moved by -(piece.x,
// piece.y) so the piece lands at the lower left, then the lower left copied to the piece's place:
// the depth buffer into a depth texture (`depth`), else the draw buffer's colour. The caller has
// applied a RenderState with the scissor test on and set the clear values; the texture binding of
// the active unit is left at 0.
void draw_through_main_buffer(GLuint texture, const std::vector<MapPiece>& pieces, bool depth, GLbitfield clear,
                              const std::function<void(const MapPiece&)>& draw);

}  // namespace dsr
