// Reinhard tone map (docs/design.md §2: Ls = key·L/Lavg, colour = Ls/(1+Ls)), then Phong
// specular added after tone mapping (thesis §3.2.2), then sRGB encoding.
uniform sampler2D u_radiance;
uniform sampler2D u_position;
uniform sampler2D u_normal;
uniform vec3 u_eye;
uniform float u_key;
uniform float u_lavg;
uniform float u_specular;   // Phong ks; 0 turns it off
uniform float u_shininess;
layout(location = 0) out vec4 o_color;

vec3 srgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 p = texelFetch(u_position, px, 0);
    if (p.w == 0.0) {
        // Background: a dark vertical gradient.
        float t = gl_FragCoord.y / float(textureSize(u_position, 0).y);
        o_color = vec4(srgb(vec3(mix(0.004, 0.03, t))), 1.0);
        return;
    }
    vec3 n = normalize(texelFetch(u_normal, px, 0).xyz);
    vec3 v = normalize(u_eye - p.xyz);
    if (dot(n, v) < 0.0) n = -n;
    vec3 ls = u_key * texelFetch(u_radiance, px, 0).rgb / max(u_lavg, 1e-30);
    vec3 c = ls / (1.0 + ls);
    if (u_specular > 0.0) {
        // A constant trip count (unrolled, so the light uniforms are read at
        // constant indices: llvmpipe gathers dynamically indexed ones per lane).
        for (int i = 0; i < MAX_LIGHTS; ++i) {
            if (i >= u_lightCount) break;
            float falloff;
            vec3 l = toLight(i, p.xyz, falloff);
            if (dot(n, l) <= 0.0) continue;
            float s = pow(max(dot(reflect(-l, n), v), 0.0), u_shininess);
            // Outside the lobe the highlight is below an 8-bit step: skip the
            // shadow taps (most pixels; they cost most of this pass).
            if (u_specular * s < 1e-4) continue;
            vec3 tint = u_lightRgb[i] / max(max(u_lightRgb[i].r, u_lightRgb[i].g), max(u_lightRgb[i].b, 1e-30));
            c += u_specular * s * tint * visibility(i, p.xyz, n, l);
        }
    }
    o_color = vec4(srgb(c), 1.0);
}
