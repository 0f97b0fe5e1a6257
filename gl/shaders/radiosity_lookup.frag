// B at the frame's pixels from a method's copy over the atlas
// (gl/radiosity_lookup.h; docs/design.md §6 "B over the atlas"), the
// composite's input on a frame that only moved the camera. The rule is
// kernels/radiosity_atlas.cl's: bilinear over the 2×2 texels around the
// pixel's atlas coordinates that hold its surface (covered or of the ring,
// of its medium, within sqrt(u_maxMm2) in space), renormalised; a = 1.
// A pixel with none (a sliver chart holds no texel centre) is counted in
// u_offAtlas and marked a = -1; with TSIS_FILL, a second pass over those
// gives each the B of its nearest neighbour in space among the 3×3 of its
// medium that the lookup found (a = 1; the pass' own writes, a = 0.5, are
// never read, so the order of its fragments does not matter). The CL path
// gathers such a pixel at its point instead.
uniform sampler2D u_position;  // the frame's G-buffer: xyz, w = medium tag
uniform sampler2D u_uv;        // its atlas coordinates
uniform sampler2D u_atlasXyz;  // the copy's texel positions (w = medium tag, 0 none)
uniform sampler2D u_atlasB;    // and B
uniform float u_maxMm2;
layout(location = 0) out vec4 o_b;

#ifndef TSIS_FILL
// The depth test before the shader, as without the counter (a shader with
// side effects is otherwise tested after: every pixel shaded).
layout(early_fragment_tests) in;
layout(binding = 0, offset = 0) uniform atomic_uint u_offAtlas;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 p = texelFetch(u_position, px, 0);
    int res = textureSize(u_atlasXyz, 0).x;
    vec2 f = texelFetch(u_uv, px, 0).xy * float(res) - 0.5;
    vec2 f0 = floor(f);
    vec2 t = f - f0;
    ivec2 c0 = ivec2(f0);
    vec4 sum = vec4(0.0), all4 = vec4(0.0);
    float weights = 0.0, n = 0.0;
    // Selects, not branches (llvmpipe runs both sides of a branch anyway;
    // 2.45 -> 1.8 ms at 512²); a texel outside the atlas read clamped and
    // not counted; an undefined texel's B never multiplied, only not added.
    for (int j = 0; j < 4; ++j) {
        ivec2 k = c0 + ivec2(j & 1, j >> 1);
        bool inside = all(greaterThanEqual(k, ivec2(0))) && all(lessThan(k, ivec2(res)));
        ivec2 kc = clamp(k, ivec2(0), ivec2(res - 1));
        vec4 q = texelFetch(u_atlasXyz, kc, 0);
        vec3 d = q.xyz - p.xyz;
        bool own = inside && q.w == p.w && dot(d, d) < u_maxMm2;
        float w = ((j & 1) != 0 ? t.x : 1.0 - t.x) * ((j >> 1) != 0 ? t.y : 1.0 - t.y);
        vec4 b = texelFetch(u_atlasB, kc, 0);
        sum += own ? w * b : vec4(0.0);
        weights += own ? w : 0.0;
        all4 += own ? b : vec4(0.0);
        n += own ? 1.0 : 0.0;
    }
    if (n == 0.0) {
        atomicCounterIncrement(u_offAtlas);
        o_b = vec4(0.0, 0.0, 0.0, -1.0);
        return;
    }
    // Its own texels all at weight 0 (on the far edge of its cell): their mean.
    vec4 v = weights > 0.0 ? sum / weights : all4 / n;
    o_b = vec4(v.xyz, 1.0);
}
#else
uniform sampler2D u_b;  // the lookup's output, this pass' target (a texture barrier between)

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    if (texelFetch(u_b, px, 0).a != -1.0) discard;
    vec4 p = texelFetch(u_position, px, 0);
    ivec2 size = textureSize(u_position, 0);
    vec3 best = vec3(0.0);
    float bestD2 = 1e30;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 k = clamp(px + ivec2(dx, dy), ivec2(0), size - 1);
            vec4 b = texelFetch(u_b, k, 0);
            vec4 q = texelFetch(u_position, k, 0);
            vec3 d = q.xyz - p.xyz;
            if (b.a == 1.0 && q.w == p.w && dot(d, d) < bestD2) {
                bestD2 = dot(d, d);
                best = b.rgb;
            }
        }
    // None around: left dark.
    o_b = vec4(best, 0.5);
}
#endif
