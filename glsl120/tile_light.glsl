// One light's term at a pixel of a tile, as the tiles' light shaders add it (light_tiles.frag,
// which reads the light from the batch's arrays at every pixel, and light_tiles_flat.frag, which
// takes it from the vertex shader): the light's five vec4s as lighting.glsl's light_contribution
// takes them. False, t untouched, where light.frag's per-light tests (LIGHT_DEPTH_TEST,
// LIGHT_SPHERE_TEST) leave the pixel out of the light, as they discard it from the light's quad.
bool tile_light_term(vec4 lp, vec4 lc, vec4 ld, vec4 ls, vec4 la, vec3 pos, vec3 v, vec3 normal, vec3 diffuse,
                     vec3 specular, float shininess, out vec3 t)
{
    t = vec3(0.0);
    float type = lc.w;
#ifdef POINT_LIGHTS
    type = 0.0;
#endif
    // The depth test only where the sphere test is off: a point outside the depth span is outside
    // the sphere too (|dz| > r gives dot(d, d) >= r * r, rounding being monotonic), and the span's
    // test before the sphere's only adds work (docs/light_loop_cpu.md, "The tests in the shader").
#if defined(LIGHT_DEPTH_TEST) && !defined(LIGHT_SPHERE_TEST)
    if (type < 1.5 && abs(pos.z - lp.z) > lp.w)
        return false;
#endif
#ifdef LIGHT_SPHERE_TEST
    // The vector from pos to the light, as light_contribution takes it (l = Lpos.xyz - p), so the
    // compiler computes it and dot(l, l) once for both, where the test's pos - light (its negation,
    // the same squares) would be computed apart (docs/light_loop_cpu.md, "Smaller choices in the
    // shaders").
    vec3 l = lp.xyz - pos;
    if (type < 1.5 && dot(l, l) >= lp.w * lp.w)
        return false;
#ifndef POINT_LIGHTS
    if (type > 0.5 && type < 1.5 && -dot(l, ld.xyz) <= length(l) * ld.w)
        return false;
#endif
#endif
    t = light_contribution(lp, lc, ld, ls, la, pos, v, normal, diffuse, specular, shininess);
    return true;
}

// A term as its own pass would have blended it: clamped to [0, 1] as the blend clamps (a float
// P-buffer 0, ACCUM_FLOAT, clamps nothing) and, into the RGBA8 P-buffer 0, rounded to the 8-bit
// step that pass would have written, as this GL rounds: the sum then matches the quad geometry's
// image instead of differing by up to N/2 LSB. QUANTIZE_8BIT: bytes, summed exactly; the shader
// scales the sum once.
vec3 tile_light_blended(vec3 t)
{
#ifndef ACCUM_FLOAT
    t = clamp(t, 0.0, 1.0);
#endif
#ifdef QUANTIZE_8BIT
    t = quantize8_byte(t);
#endif
    return t;
}
