// L = Ft(η, cos θo) / π · B (docs/design.md §2), per covered pixel, times
// u_exitScale: 1 (Jensen's exit term) or 1/c (pbrt's normalised one, --exit).
uniform sampler2D u_radiosity;
uniform sampler2D u_position;
uniform sampler2D u_normal;
uniform vec3 u_eye;
uniform float u_exitScale;
layout(location = 0) out vec4 o_radiance;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 p = texelFetch(u_position, px, 0);
    if (p.w == 0.0) {
        o_radiance = vec4(0.0);
        return;
    }
    vec3 n = normalize(texelFetch(u_normal, px, 0).xyz);
    vec3 v = normalize(u_eye - p.xyz);
    vec3 b = texelFetch(u_radiosity, px, 0).rgb;
    o_radiance = vec4(fresnelT(u_eta, abs(dot(n, v))) / PI * b * u_exitScale, 1.0);
}
