// Radiance (docs/design.md "The composite"): the subsurface term
// Ft(η, cos θo)/π · B (§2; × the exit scale: 1, Jensen's exit term, or 1/c,
// pbrt's normalised one, --exit) plus the GGX lobe's reflection of the
// lights and of the environment's residual (design "Surface reflection"); η
// and the exit scale those of the point's medium (mediumOf, by the position's w).
//
// Two variants. The frame's: one sample at each covered pixel's centre, from
// the frame's G-buffer, and (TSIS_FIND_EDGES) which covered pixels to supersample
// (the uncovered ones beside a covered one are found on the host from the
// coverage this writes: CompositePass::updateEdgePoints). With
// TSIS_COMPOSITE_SAMPLES: u_aa × u_aa samples per pixel from the composite's
// own G-buffer, only for the pixels marked (elsewhere the centre's sample
// stands for the pixel), packed: a full-screen pass over a target of one
// u_aa × u_aa block per marked pixel, in the order of u_edgePixels. Features (0 or 1, gl/shader.h
// ShaderVariants): TSIS_SPECULAR the lobe, TSIS_ENV_REFLECT the
// environment's reflection with it; the centres' TSIS_DISPLAY writes the
// display colour and the log-average's term instead of the radiance, when
// the exposure is known before the frame (no radiance image is needed then).
uniform sampler2D u_radiosity;      // B at the frame's pixels
uniform sampler2D u_framePosition;  // the frame's G-buffer positions (w = coverage)
uniform sampler2D u_normal;         // the shaded G-buffer's normals
uniform vec3 u_eye;
// The environment's reflection (render/env_reflection.h), with TSIS_ENV_REFLECT:
// the residual prefiltered by the lobe (lat-long, the map's frame, row 0 =
// up; one band of rows per layer: each medium's roughness, then with a
// roughness map the ladder's) about the mirror direction × the lobe's
// albedo (x: √cos θo; rows: one per medium, then with the ladder one per
// medium and step), × the map's intensity.
uniform sampler2D u_envPrefiltered;
uniform int u_envLayers;
uniform sampler2D u_envAlbedo;
uniform mat3 u_worldToMap;
uniform float u_envScale;
// The roughness ladder (u_ladderSteps > 1, render/env_reflection.h
// ladderRoughness): step k at R = u_ladderMin + (1 − u_ladderMin)(k/(steps − 1))²,
// prefiltered in layer u_ladderLayer + k, its albedo for medium m in row
// u_ladderRow + m·steps + k.
uniform int u_ladderSteps;
uniform int u_ladderLayer;
uniform int u_ladderRow;
uniform float u_ladderMin;
layout(location = 0) out vec4 o_radiance;

// The prefiltered residual in direction uv's layer, and the albedo in row m.
vec3 prefilteredAt(vec2 uv, float layer) {
    // Within the layer's band: its first and last rows' centres bound v.
    float rows = float(textureSize(u_envPrefiltered, 0).y) / float(u_envLayers);
    uv.y = (layer + clamp(uv.y, 0.5 / rows, 1.0 - 0.5 / rows)) / float(u_envLayers);
    return textureLod(u_envPrefiltered, uv, 0.0).rgb;
}
float albedoAt(float s, float m) {
    vec2 size = vec2(textureSize(u_envAlbedo, 0));
    return textureLod(u_envAlbedo, (vec2(s * (size.x - 1.0), m) + 0.5) / size, 0.0).r;
}

// `roughness` > 0: a roughness map's R, between two steps of the ladder;
// else the medium's (its layer `layer`).
vec3 envReflection(vec3 n, vec3 v, float tag, float layer, float roughness) {
    vec2 uv = latLongUv(normalize(u_worldToMap * reflect(-v, n)));
    float m = float(max(int(tag + 0.5) - 1, 0));
    float s = sqrt(clamp(dot(n, v), 0.0, 1.0));
    if (roughness > 0.0 && u_ladderSteps > 1) {
        float x = float(u_ladderSteps - 1) *
                  sqrt(clamp((roughness - u_ladderMin) / (1.0 - u_ladderMin), 0.0, 1.0));
        float k = min(floor(x), float(u_ladderSteps - 2)), t = x - k;
        float row = float(u_ladderRow) + m * float(u_ladderSteps) + k;
        float l0 = float(u_ladderLayer) + k;
        return u_envScale * mix(albedoAt(s, row) * prefilteredAt(uv, l0),
                                albedoAt(s, row + 1.0) * prefilteredAt(uv, l0 + 1.0), t);
    }
    return u_envScale * albedoAt(s, m) * prefilteredAt(uv, layer);
}

vec3 shade(vec4 p, ivec2 px, vec3 b) {
    vec4 nw = texelFetch(u_normal, px, 0);
    vec3 n = normalize(nw.xyz);
    vec3 v = normalize(u_eye - p.xyz);
    // An open mesh seen from behind: the side that faces the eye.
    if (dot(n, v) < 0.0) n = -n;
    vec4 medium = mediumOf(p.w);
    // B ≥ 0 where it is read: the GL side's lookup interpolates a copy whose
    // texels may hold the object transport's correction below 0 (the CL
    // side clamps at the point).
    vec3 l = fresnelT(medium.r, dot(n, v)) / PI * max(b, vec3(0.0)) * medium.g;
#if TSIS_SPECULAR
    // A roughness map's R where it covers the point, else the medium's α.
    float r = mappedRoughness(int(nw.w + 0.5) - 1);
    l += specularRadiance(p.xyz, n, v, r > 0.0 ? r * r : medium.b, medium.r);
#if TSIS_ENV_REFLECT
    l += envReflection(n, v, p.w, medium.a, r);
#endif
#endif
    return l;
}

// Whether two frame G-buffer texels show one surface: both uncovered, or
// both covered at distances to the eye within 2% (not a silhouette or a
// depth jump).
bool sameSurface(vec4 a, vec4 b) {
    if ((a.w > 0.0) != (b.w > 0.0)) return false;
    if (a.w == 0.0) return true;
    float da = distance(a.xyz, u_eye), db = distance(b.xyz, u_eye);
    return abs(da - db) <= 0.02 * max(da, db);
}

#ifdef TSIS_COMPOSITE_SAMPLES
uniform sampler2D u_position;     // the samples'
uniform sampler2D u_sampleDepth;  // their depth: < 1 where covered (colour not cleared)
uniform int u_aa;
// Marked pixel e's frame coordinates (xy) at texel (e mod width, e div width).
uniform sampler2D u_edgePixels;

// B at sample px (surface point p): the frame pixel's that holds the sample,
// or where that pixel shows no surface or another one, the covered
// neighbour's nearest to p in space.
vec3 radiosityAt(ivec2 px, vec4 p) {
    ivec2 c = px / u_aa;
    if (sameSurface(texelFetch(u_framePosition, c, 0), p)) return texelFetch(u_radiosity, c, 0).rgb;
    ivec2 size = textureSize(u_framePosition, 0);
    ivec2 best = c;
    float bestD2 = 1e30;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 k = clamp(c + ivec2(dx, dy), ivec2(0), size - 1);
            vec4 r = texelFetch(u_framePosition, k, 0);
            vec3 d = r.xyz - p.xyz;
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
    // This fragment's slot: the marked pixel, and which of its samples.
    ivec2 slot = ivec2(gl_FragCoord.xy);
    ivec2 pixel = ivec2(texelFetch(u_edgePixels, slot / u_aa, 0).xy);
    ivec2 px = pixel * u_aa + slot % u_aa;
    vec4 p = texelFetch(u_position, px, 0);
    bool covered = texelFetch(u_sampleDepth, px, 0).r < 1.0 && p.w != 0.0;
    o_radiance = covered ? vec4(shade(p, px, radiosityAt(px, p)), 1.0) : vec4(0.0);
}
#else
#if TSIS_DISPLAY
// Straight to the display: o_radiance the display colour (resolve.frag's
// tone map of this one sample), and the log-average's term.
uniform float u_scale;
layout(location = 1) out vec4 o_logLuminance;
layout(location = 2) out vec4 o_edge;
#else
layout(location = 1) out vec4 o_edge;
#endif

// A pixel whose 3×3 neighbourhood is not all one surface: a silhouette or a
// depth jump passes through it or beside it.
// (edgeTo against each neighbour, the centre's distance taken once and the
// centre itself, always its own surface, not read again.) u_framePosition is
// read here through a nearest, clamped sampler (CompositePass): constant
// offsets, no per-read clamp.
bool edgeTo(vec4 p, float dp, vec4 q) {
    if ((p.w > 0.0) != (q.w > 0.0)) return true;
    if (p.w == 0.0) return false;
    float dq = distance(q.xyz, u_eye);
    return !(abs(dp - dq) <= 0.02 * max(dp, dq));
}

bool edgePixel(vec4 p) {
    vec2 uv = gl_FragCoord.xy / vec2(textureSize(u_framePosition, 0));
    float dp = distance(p.xyz, u_eye);
    return edgeTo(p, dp, textureLodOffset(u_framePosition, uv, 0.0, ivec2(-1, -1))) ||
           edgeTo(p, dp, textureLodOffset(u_framePosition, uv, 0.0, ivec2(0, -1))) ||
           edgeTo(p, dp, textureLodOffset(u_framePosition, uv, 0.0, ivec2(1, -1))) ||
           edgeTo(p, dp, textureLodOffset(u_framePosition, uv, 0.0, ivec2(-1, 0))) ||
           edgeTo(p, dp, textureLodOffset(u_framePosition, uv, 0.0, ivec2(1, 0))) ||
           edgeTo(p, dp, textureLodOffset(u_framePosition, uv, 0.0, ivec2(-1, 1))) ||
           edgeTo(p, dp, textureLodOffset(u_framePosition, uv, 0.0, ivec2(0, 1))) ||
           edgeTo(p, dp, textureLodOffset(u_framePosition, uv, 0.0, ivec2(1, 1)));
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 p = texelFetch(u_framePosition, px, 0);
    // r: supersample; g: covered (the depth test lets only covered pixels here).
    o_edge = vec4(TSIS_FIND_EDGES != 0 && edgePixel(p) ? 1.0 : 0.0, 1.0, 0.0, 0.0);
    vec4 l = p.w == 0.0 ? vec4(0.0) : vec4(shade(p, px, texelFetch(u_radiosity, px, 0).rgb), 1.0);
#if TSIS_DISPLAY
    vec3 background = backgroundAt(gl_FragCoord.xy, u_scale);
    o_radiance = vec4(srgb(exposed(l, u_scale, background)), u_background == 1 ? l.a : 1.0);
    o_logLuminance = logLuminance(l);
#else
    o_radiance = l;
#endif
}
#endif
