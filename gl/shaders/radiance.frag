// L = Ft(η, cos θo) / π · B (docs/design.md §2), per covered pixel, times
// the exit scale: 1 (Jensen's exit term) or 1/c (pbrt's normalised one,
// --exit); η and the scale those of the pixel's medium (mediumOf).
uniform sampler2D u_radiosity;
uniform sampler2D u_position;
uniform sampler2D u_normal;
uniform vec3 u_eye;
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
    vec4 medium = mediumOf(p.w);
    o_radiance = vec4(fresnelT(medium.r, abs(dot(n, v))) / PI * b * medium.g, 1.0);
}
