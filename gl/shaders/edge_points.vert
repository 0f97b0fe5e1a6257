// One point per supersampled frame pixel, the pixel read from its slot in
// u_edgePixels (CompositePass keeps the list, made from the centre pass'
// marks when the G-buffer changes), for resolve.frag's average of its
// samples (a fullscreen pass that discards the others costs llvmpipe nearly
// as much as shading every sample, and a point for every pixel costs its
// vertex pipeline 262K vertices at 512²).
uniform sampler2D u_edgePixels;  // pixel e's (x, y) at texel (e mod width, e div width)
// u_frameSize: common.glsl's.
flat out ivec2 v_slot;  // the point's slot: its samples' block (radiance.frag)

void main() {
    int columns = textureSize(u_edgePixels, 0).x;
    v_slot = ivec2(gl_VertexID % columns, gl_VertexID / columns);
    vec2 pixel = texelFetch(u_edgePixels, v_slot, 0).xy;
    gl_Position = vec4((pixel + 0.5) / u_frameSize * 2.0 - 1.0, 0.0, 1.0);
}
