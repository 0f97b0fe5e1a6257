// Flux per atlas texel = E(x) · texel surface area (docs/design.md §2), so the atlas
// sums to the total flux the object receives. Runs over the geometry atlas,
// so a moving light re-shades texels without re-rasterising the mesh.
uniform sampler2D u_position;
uniform sampler2D u_normal;
// With TSIS_ENV, the environment's residual E per texel (render/env_light.h).
uniform sampler2D u_envIrradiance;
layout(location = 0) out vec4 o_flux;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 p = texelFetch(u_position, px, 0);
    if (p.w == 0.0) {
        o_flux = vec4(0.0);
        return;
    }
    vec4 n = texelFetch(u_normal, px, 0);
    // The entry's cosine at the normal map's normal (the texel's area stays
    // the geometry's).
    vec3 e = irradiance(p.xyz, shadingNormal(n.xyz, (vec2(px) + 0.5) / vec2(textureSize(u_normal, 0))),
                        mediumOf(p.w).r);
#if TSIS_ENV
    e += texelFetch(u_envIrradiance, px, 0).rgb;
#endif
    o_flux = vec4(e * n.w, 1.0);
#if TSIS_TEXTURED
    o_flux.rgb *= texelFetch(u_albedo, px, 0).rgb;
#endif
}
