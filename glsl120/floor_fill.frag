#version 120
// The bench's G-buffer fill floor: a trivial shader writing a constant into each of the
// G-buffer's TARGETS colour targets (3, or 4 with the packed depth target), so the pass pays
// for rasterising the triangles and writing the same formats, and nothing else.
void main()
{
    gl_FragData[0] = vec4(0.5, 0.5, 1.0, 1.0);
    gl_FragData[1] = vec4(0.8, 0.8, 0.8, 1.0);
    gl_FragData[2] = vec4(0.2, 0.2, 0.2, 0.5);
#if TARGETS > 3
    gl_FragData[3] = vec4(0.25, 0.5, 0.75, 0.0);
#endif
}
