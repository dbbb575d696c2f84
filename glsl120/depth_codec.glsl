// Depth <-> RGB8 colour, for GPUs without depth textures (§3.3.2). CPU twins and their
// round-trip tests: src/deferred/depth_codec.{h,cpp}, tests/test_depth_codec.cpp.
// Every pass that needs the surface's eye z or eye position calls surface_eye_z /
// surface_eye_pos below, so one define picks the source for all of them: the depth texture
// (none), the packed target (PACKED_DEPTH + ENC_*), or the position paths' float target
// (POSITION_TARGET: --depth position16|position32, eye-space xyz written by the material pass).

// Listing 11 exactly as written: bytes as k/256. An 8-bit target stores round(c*255)
// and returns byte/255, so this does not survive the target (docs/errata.md).
vec3 pack_depth_literal(float f)
{
    vec3 color;
    f *= 256.0;
    color.x = floor(f);
    f = (f - color.x) * 256.0;
    color.y = floor(f);
    color.z = f - color.y;
    color.xy *= 0.00390625;  // *= 1.0/256
    return color;
}

// Listing 18 exactly as written.
float unpack_depth_literal(vec3 color)
{
    const vec3 byte_to_float = vec3(1.0, 1.0 / 256.0, 1.0 / (256.0 * 256.0));
    return dot(color, byte_to_float);
}

// Corrected base-256 packing: a 24-bit integer code k written as three bytes, each as
// byte/255 so the RGB8 target keeps it exactly. Float arithmetic is exact below 2^24.
vec3 pack_depth(float d)
{
    d = clamp(d, 0.0, 1.0);
    // Not floor(d*16777215.0 + 0.5): above 2^23 the float ulp is 1, so the product is already
    // rounded and "+ 0.5" ties to even, off by one for a quarter of all codes
    // (tests/test_depth_codec.cpp). d*2^24 is exact, and d*16777215 = floor(m) + (fract(m) - d).
    float m = d * 16777216.0;
    float k = floor(m) + floor(fract(m) - d + 0.5);
    float b0 = floor(k / 65536.0);
    k -= b0 * 65536.0;
    float b1 = floor(k / 256.0);
    float b2 = k - b1 * 256.0;
    return vec3(b0, b1, b2) / 255.0;
}

float unpack_depth(vec3 c)
{
    vec3 b = floor(c * 255.0 + 0.5);
    return (b.x * 65536.0 + b.y * 256.0 + b.z) / 16777215.0;
}

// What the packed target holds (--depth-encoding; one of ENC_LITERAL, ENC_LINEAR, ENC_LOG, else
// the corrected packing of the window depth). zrange = (near, far, log2(far/near)); planes as
// §3.4.3. log2/exp2 rather than log/exp: Mesa lowers the natural ones to log2/exp2 and a
// multiply, one more rounding each way (2.2e-6 instead of 1.2e-6 relative z at 1e6). CPU twins: encode_eye_z / decode_eye_z in src/deferred/depth_codec.cpp.
vec3 packed_encode(float z, vec2 planes, vec3 zrange)
{
#if defined(ENC_LITERAL)
    return pack_depth_literal((planes.x * z + planes.y) / -z);  // Listing 13 line 27
#elif defined(ENC_LINEAR)
    return pack_depth((-z - zrange.x) / (zrange.y - zrange.x));
#elif defined(ENC_LOG)
    return pack_depth(log2(-z / zrange.x) / zrange.z);
#else
    return pack_depth((planes.x * z + planes.y) / -z);
#endif
}

float packed_eye_z(vec3 c, vec2 planes, vec3 zrange)
{
#if defined(ENC_LITERAL)
    return -planes.y / min(planes.x + unpack_depth_literal(c), planes.y / zrange.y);  // Listing 20 line 21
#elif defined(ENC_LINEAR)
    return -(zrange.x + unpack_depth(c) * (zrange.y - zrange.x));
#elif defined(ENC_LOG)
    return -zrange.x * exp2(unpack_depth(c) * zrange.z);
#else
    return -planes.y / min(planes.x + unpack_depth(c), planes.y / zrange.y);
#endif
}

// Eye-space z of the surface at uv: from the depth texture (§3.4.3), the packed target, or the
// stored position.
float surface_eye_z(sampler2D depth_map, vec2 uv, vec2 planes, vec3 zrange)
{
#if defined(POSITION_TARGET)
    return texture2D(depth_map, uv).z;
#elif defined(PACKED_DEPTH)
    return packed_eye_z(texture2D(depth_map, uv).rgb, planes, zrange);
#else
    // Listing 20's pos.z = -planes.y/(planes.x+depth). The denominator is at most its far-plane
    // value planes.y/far: past far/near ~1e7 planes.x rounds to -1 in float, and depth 1.0
    // would divide by zero.
    return -planes.y / min(planes.x + texture2D(depth_map, uv).r, planes.y / zrange.y);
#endif
}

// Eye-space position of the surface at uv. From depth: z as surface_eye_z, x and y along the
// pixel's eye-space view ray (Listing 20: pos.xy = vpos.xy / vpos.z * pos.z; rays as Listing 19's
// clean form, z = -1). POSITION_TARGET: the position the material pass stored, no reconstruction.
vec3 surface_eye_pos(sampler2D depth_map, vec2 uv, vec3 ray, vec2 planes, vec3 zrange)
{
#ifdef POSITION_TARGET
    return texture2D(depth_map, uv).xyz;
#else
    float z = surface_eye_z(depth_map, uv, planes, zrange);
    return vec3(ray.xy / ray.z * z, z);
#endif
}
