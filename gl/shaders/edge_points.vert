// One point per supersampled frame pixel (CompositePass keeps their list,
// made from the centre pass' marks when the G-buffer changes), u_pointSize
// wide: on the composite's sample grid (u_aa) it covers the pixel's u_aa ×
// u_aa samples, so only they are shaded; on the frame's (1), the pixel, for
// resolve.frag's average of them (a fullscreen pass that discards the
// others costs llvmpipe nearly as much as shading every sample, and a point
// for every pixel costs its vertex pipeline 262K vertices at 512²).
layout(location = 0) in vec2 a_pixel;
uniform vec2 u_frameSize;
uniform float u_pointSize;
flat out int v_edge;  // the point's place in the list (its samples' slot)

void main() {
    v_edge = gl_VertexID;
    gl_PointSize = u_pointSize;
    gl_Position = vec4((a_pixel + 0.5) / u_frameSize * 2.0 - 1.0, 0.0, 1.0);
}
