// The log-average's sums on the GPU side: each fragment adds up its
// u_block × u_block pixels of resolve.frag's log luminance, (Σ log Y, count);
// the host adds the few fragments (CompositePass::logAverageLuminance), so no
// frame of floats is read back for it.
uniform sampler2D u_logLuminance;
uniform int u_block;
layout(location = 0) out vec4 o_sum;

void main() {
    ivec2 size = textureSize(u_logLuminance, 0);
    ivec2 first = ivec2(gl_FragCoord.xy) * u_block;
    ivec2 last = min(first + u_block, size);
    vec2 sum = vec2(0.0);
    for (int y = first.y; y < last.y; ++y)
        for (int x = first.x; x < last.x; ++x) sum += texelFetch(u_logLuminance, ivec2(x, y), 0).xy;
    o_sum = vec4(sum, 0.0, 0.0);
}
