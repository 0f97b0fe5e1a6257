// Radiance per sample of the composite's geometry (u_aa × u_aa samples per
// frame pixel, docs/design.md "The composite"): the subsurface term Ft(η, cos θo)/π · B
// (§2; × u_exitScale: 1, Jensen's exit term, or 1/c, pbrt's normalised one,
// --exit) plus the GGX lobe's reflection of the lights (design "Surface reflection").
uniform sampler2D u_radiosity;      // B at the frame's pixels
uniform sampler2D u_framePosition;  // the frame's G-buffer positions (w = coverage)
uniform sampler2D u_position;       // the samples' (u_aa × the frame's size)
uniform sampler2D u_normal;
uniform int u_aa;
uniform vec3 u_eye;
uniform float u_exitScale;
uniform float u_alpha;  // GGX α = R²; 0: no lobe (--no-specular)
layout(location = 0) out vec4 o_radiance;

// B at sample px (surface point p): the frame pixel's that holds the sample,
// or where that pixel shows no surface or another one (a silhouette, a depth
// jump), the covered neighbour's nearest to p in space. At 1× the sample is
// the pixel itself.
vec3 radiosityAt(ivec2 px, vec3 p) {
    ivec2 c = px / u_aa;
    vec4 q = texelFetch(u_framePosition, c, 0);
    float depth = distance(p, u_eye);
    if (q.w > 0.0 && abs(distance(q.xyz, u_eye) - depth) <= 0.02 * depth)
        return texelFetch(u_radiosity, c, 0).rgb;
    ivec2 size = textureSize(u_framePosition, 0);
    ivec2 best = c;
    float bestD2 = 1e30;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 k = clamp(c + ivec2(dx, dy), ivec2(0), size - 1);
            vec4 r = texelFetch(u_framePosition, k, 0);
            vec3 d = r.xyz - p;
            if (r.w > 0.0 && dot(d, d) < bestD2) {
                bestD2 = dot(d, d);
                best = k;
            }
        }
    // A sliver thinner than the frame's pixels: no covered pixel holds it.
    if (bestD2 == 1e30) return vec3(0.0);
    return texelFetch(u_radiosity, best, 0).rgb;
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 p = texelFetch(u_position, px, 0);
    if (p.w == 0.0) {
        o_radiance = vec4(0.0);
        return;
    }
    vec3 n = normalize(texelFetch(u_normal, px, 0).xyz);
    vec3 v = normalize(u_eye - p.xyz);
    // An open mesh seen from behind: the side that faces the eye.
    if (dot(n, v) < 0.0) n = -n;
    vec3 l = fresnelT(u_eta, dot(n, v)) / PI * radiosityAt(px, p.xyz) * u_exitScale;
    if (u_alpha > 0.0) l += specularRadiance(p.xyz, n, v, u_alpha);
    o_radiance = vec4(l, 1.0);
}
