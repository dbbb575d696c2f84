// One batch's shadow maps in one texture, for the batched light passes (tiles, screen; shadow.glsl
// SHADOW_ATLAS): GLSL 1.20 indexes an array of samplers only by a constant, so a batch of K maps on
// K units is read through an if-chain over the slots, and a CPU rasteriser (llvmpipe) runs every
// branch: K map reads a lookup. Copied into one atlas, the lookup reads one sampler at the slot's
// region (atlas_layout.h). The atlas has the maps' format (a depth texture compared by ARB_shadow,
// or RGB8 on the packed path), filtered GL_NEAREST: the lookup weighs the 2x2 itself (shadow.glsl
// says why); each map is copied with glCopyTexSubImage2D from a
// framebuffer object that has it attached, and again only when the shadow stage drew it anew
// (ShadowLookup::generation) or the batch's maps or their places changed. Needs framebuffer objects.
#pragma once
#include <vector>

#include "deferred/atlas_layout.h"
#include "deferred/frame.h"
#include "gl/gl.h"

namespace dsr {

class ShadowAtlas {
public:
    // packed: RGB8 maps, else depth textures.
    explicit ShadowAtlas(bool packed);
    ~ShadowAtlas();
    ShadowAtlas(const ShadowAtlas&) = delete;
    ShadowAtlas& operator=(const ShadowAtlas&) = delete;
    // maps[k] into layout.regions[k] (layout fits; the maps' sizes are its regions'); copies only
    // what the atlas does not already hold there. Returns the texels copied. Leaves the draw
    // framebuffer and the active texture unit as it found them; the atlas stays bound on `unit`.
    long long update(const AtlasLayout& layout, const std::vector<const ShadowLookup*>& maps, int unit);
    GLuint texture() const { return texture_; }

private:
    struct Held {
        unsigned texture = 0, generation = 0;
    };
    void allocate(int width, int height);

    bool packed_;
    GLuint texture_ = 0, read_fbo_ = 0;
    AtlasLayout layout_;        // what the texture holds
    std::vector<Held> held_;    // per region of layout_
};

}  // namespace dsr
