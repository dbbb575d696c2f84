#version 120
// The bench's G-buffer fill floor (src/analysis/bench_floor.h): the scene's triangles with
// nothing but their position, transformed as the depth pre-pass transforms them.
void main()
{
    gl_Position = ftransform();
}
