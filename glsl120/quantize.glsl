// A colour rounded to 8 bits as this GL rounds a fragment written into an RGBA8 target
// (gl/rounding_probe.h, measured once; shader_table.cpp picks the define): one pass that sums what
// several passes would have blended rounds each term as its own pass would (light_tiles.frag's
// lights, light.frag's ambient fold). To nearest with an exact tie to the even byte
// (QUANTIZE_TIES_EVEN, llvmpipe; floor(v + 0.5) alone took every tie up, and where a pixel's terms
// held two even ties, 1024-overlap at 384x384, it was 2 LSB off quad); QUANTIZE_TRUNCATE 2^n where
// the GL truncates to n bits first and rounds ties down (docs/gpu.md, "Images on a GPU"); where no
// model fits, floor(t x 255 + quantize_round), 1 - the median threshold.
#ifdef QUANTIZE_8BIT
uniform float quantize_round;  // the fallback's offset where no model fits

// The byte (0..255, as a float) an RGBA8 target stores for t in [0, 1].
vec3 quantize8_byte(vec3 t)
{
#ifdef QUANTIZE_TRUNCATE
    // This GL's colour to 2^-n first, then to nearest with a tie down.
    t = floor(t * QUANTIZE_TRUNCATE) / QUANTIZE_TRUNCATE;
    return ceil(t * 255.0 - 0.5);
#elif defined(QUANTIZE_TIES_EVEN)
    // round(t x 255), a tie to even (llvmpipe), from h = t x 255 / 2 (exact halving), its floor m
    // and g = h - m (exact): 2m + [g > 1/4] + [g >= 3/4], a tie (g = 1/4 or 3/4) going to the even
    // byte. Cheaper on llvmpipe than floor(t x 255 + 0.5) less the tie's odd step (mod, equal;
    // docs/light_loop_cpu.md, "Smaller choices in the shaders").
    vec3 h = t * 127.5;
    vec3 m = floor(h);
    vec3 g = h - m;
    return 2.0 * m + vec3(greaterThan(g, vec3(0.25))) + step(0.75, g);
#else
    return floor(t * 255.0 + quantize_round);
#endif
}

vec3 quantize8(vec3 t)
{
    return quantize8_byte(t) / 255.0;
}

// What a sampler reads back from an RGBA8 target t was written into: the stored byte x (1/255), as
// llvmpipe converts (x / 255.0 differs from it in the last bit, and Listing 15's ambient x diffuse
// can land on a rounding tie: material.frag's ambient target multiplies what the ambient pass reads).
vec3 texel8(vec3 t)
{
    return quantize8_byte(t) * (1.0 / 255.0);
}
#endif
