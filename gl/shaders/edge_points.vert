// One point per frame pixel, u_aa samples wide: on the composite's sample
// grid it covers the pixel's u_aa × u_aa samples. Only the pixels marked in
// u_edges are drawn (the others are moved outside the clip volume), so the
// samples are shaded only where a silhouette or depth jump passes: a
// fullscreen pass that discards elsewhere costs llvmpipe nearly as much as
// shading every sample.
uniform sampler2D u_edges;
uniform int u_aa;

void main() {
    ivec2 size = textureSize(u_edges, 0);
    ivec2 c = ivec2(gl_VertexID % size.x, gl_VertexID / size.x);
    gl_PointSize = float(u_aa);
    gl_Position = texelFetch(u_edges, c, 0).r > 0.0
                      ? vec4((vec2(c) + 0.5) / vec2(size) * 2.0 - 1.0, 0.0, 1.0)
                      : vec4(2.0, 2.0, 2.0, 1.0);
}
