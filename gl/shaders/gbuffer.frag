// Camera G-buffer: world position (w = the medium tag 1 + medium, 0 where
// uncovered), normal (w: below), and with
// TSIS_GBUFFER_IRRADIANCE (0 or 1, gl/shader.h ShaderVariants) the irradiance E(x) at the pixel's surface point
// (for camera-view methods such as LSS; the shadow taps cost most of the pass),
// and with TSIS_GBUFFER_UV the pixel's atlas coordinates (the pyramid reads B
// from its texture-space copy there, render/method_pyramid.h).
uniform vec3 u_eye;
in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
flat in float v_medium;
layout(location = 0) out vec4 o_position;
layout(location = 1) out vec4 o_normal;
#if TSIS_GBUFFER_IRRADIANCE
layout(location = 2) out vec4 o_irradiance;
// The environment's residual E per atlas texel (render/env_light.h), when
// u_hasEnv: the flux atlas's, read at the pixel's atlas texel.
uniform sampler2D u_envIrradiance;
uniform int u_hasEnv;
#endif
#if TSIS_GBUFFER_UV && TSIS_GBUFFER_IRRADIANCE
layout(location = 3) out vec2 o_uv;
#elif TSIS_GBUFFER_UV
layout(location = 2) out vec2 o_uv;
#endif

void main() {
    vec3 g = normalize(v_normal);
    vec3 n = shadingNormal(g, v_uv);
    if (u_normalMapped) {
        // A mapped normal turned away from the eye (at grazing view): moved
        // back to just inside the hemisphere of the side the eye sees (the
        // composite shades that side), else its exit and lobe are dark.
        vec3 v = normalize(u_eye - v_position);
        float s = dot(g, v) < 0.0 ? -1.0 : 1.0;
        float c = s * dot(n, v);
        if (c < 0.05) n = normalize(n + s * (0.05 - c) * v);
    }
    o_position = vec4(v_position, v_medium);
    // With an albedo atlas or a roughness map, the normal's w is the pixel's
    // atlas texel + 1 (the host reads its exit factor there,
    // render/albedo_atlas.h; the composite its roughness), else 1.
    vec2 size = vec2(u_textured ? textureSize(u_albedo, 0) : textureSize(u_surfaceMaps, 0));
    vec2 texel = min(floor(v_uv * size), size - 1.0);
    o_normal = vec4(n, u_textured || u_roughnessMapped ? 1.0 + texel.y * size.x + texel.x : 1.0);
#if TSIS_GBUFFER_IRRADIANCE
    vec3 e = irradiance(v_position, n, mediumOf(v_medium).r);
    if (u_hasEnv != 0) {
        ivec2 size = textureSize(u_envIrradiance, 0);
        e += texelFetch(u_envIrradiance, min(ivec2(v_uv * vec2(size)), size - 1), 0).rgb;
    }
    o_irradiance = vec4(e * albedoFactor(v_uv), 1.0);
#endif
#if TSIS_GBUFFER_UV
    o_uv = v_uv;
#endif
}
