#version 120
// The bench's per-fragment floor of a light pass (src/analysis/bench_floor.h): one read of each
// of the four G-buffer targets the light shader reads (normal, diffuse, specular, depth) and one
// colour written; no lighting arithmetic. The reads are summed so none can be optimised away.
uniform sampler2D t0;  // unit 0: normal
uniform sampler2D t1;  // unit 1: diffuse
uniform sampler2D t2;  // unit 2: specular
uniform sampler2D t3;  // unit 3: depth texture, or the packed depth target

varying vec2 texcoord;

void main()
{
    gl_FragColor = 0.25 * (texture2D(t0, texcoord) + texture2D(t1, texcoord) + texture2D(t2, texcoord) +
                           texture2D(t3, texcoord));
}
