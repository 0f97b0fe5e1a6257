// Prepended (after #version) to every tsis shader stage.
const float PI = 3.14159265358979;
// MAX_LIGHTS: defined before this file by ShaderProgram (TSIS_MAX_LIGHTS).

// Exact unpolarized Fresnel reflectance from air into a medium of relative
// index eta (docs/design.md §2: not Schlick).
float fresnelR(float eta, float cosI) {
    cosI = clamp(cosI, 0.0, 1.0);
    float sin2T = (1.0 - cosI * cosI) / (eta * eta);
    float cosT = sqrt(max(0.0, 1.0 - sin2T));
    float rs = (cosI - eta * cosT) / (cosI + eta * cosT);
    float rp = (eta * cosI - cosT) / (eta * cosI + cosT);
    return 0.5 * (rs * rs + rp * rp);
}
float fresnelT(float eta, float cosI) { return 1.0 - fresnelR(eta, cosI); }

// Lights (docs/design.md §2): type 0 = point (vec = position, rgb = intensity),
// 1 = directional (vec = direction of travel, rgb = irradiance).
uniform int u_lightCount;
uniform int u_lightType[MAX_LIGHTS];
uniform vec3 u_lightVec[MAX_LIGHTS];
uniform vec3 u_lightRgb[MAX_LIGHTS];
uniform mat4 u_lightViewProj[MAX_LIGHTS];
uniform float u_shadowTexelMm[MAX_LIGHTS];  // a shadow-map texel's size at the object
uniform int u_lightShadows[MAX_LIGHTS];      // 0: the light casts no shadows (V = 1)
// One layer per light: a single sampler, since dynamically indexed sampler
// arrays cost one lookup per array element on llvmpipe.
uniform sampler2DArrayShadow u_shadowMaps;
// Per medium (gl/material_tables.h): r = η, g = the exit term's scale, b =
// the surface's GGX α, a = its layer of the prefiltered environment; texel
// m = tag − 1 at (m mod 4096, m / 4096).
uniform sampler2D u_media;
vec4 mediumOf(float tag) {
    int m = max(int(tag + 0.5) - 1, 0);
    return texelFetch(u_media, ivec2(m % 4096, m / 4096), 0);
}
// With u_textured, the albedo factor of each atlas texel (render/albedo_atlas.h):
// light entering there is scaled by it, light leaving too.
// A uniform, or a constant in a program compiled for one case (TSIS_TEXTURED
// defined 0 or 1: gl/shader.h ShaderVariants), where an untextured scene's
// program has no albedo lookups to run.
uniform sampler2D u_albedo;
#ifdef TSIS_TEXTURED
const bool u_textured = TSIS_TEXTURED != 0;
#else
uniform bool u_textured;
#endif
vec3 albedoFactor(vec2 atlasUv) {
    return u_textured ? texture(u_albedo, atlasUv).rgb : vec3(1.0);
}
// The surface maps of each atlas texel (render/surface_atlas.h): with
// u_normalMapped, the normal maps' shading normal (xyz; (0, 0, 0) where none:
// the geometry's normal n); with u_roughnessMapped, the roughness maps' R (w;
// 0 where none: the medium's). Nearest, not bilinear: a texel beside one
// without a map keeps its own.
uniform sampler2D u_surfaceMaps;
uniform bool u_normalMapped;
uniform bool u_roughnessMapped;
vec3 shadingNormal(vec3 n, vec2 atlasUv) {
    if (!u_normalMapped) return n;
    ivec2 size = textureSize(u_surfaceMaps, 0);
    vec3 m = texelFetch(u_surfaceMaps, clamp(ivec2(atlasUv * vec2(size)), ivec2(0), size - 1), 0).xyz;
    return dot(m, m) > 0.0 ? m : n;
}
// The roughness map's R at atlas texel index `texel` (the G-buffer normal's
// w − 1), 0 where none.
float mappedRoughness(int texel) {
    if (!u_roughnessMapped || texel < 0) return 0.0;
    int width = textureSize(u_surfaceMaps, 0).x;
    return texelFetch(u_surfaceMaps, ivec2(texel % width, texel / width), 0).w;
}

// Unit vector from p towards light i, and the 1/d² falloff of a point light.
vec3 toLight(int i, vec3 p, out float falloff) {
    if (u_lightType[i] == 0) {
        vec3 d = u_lightVec[i] - p;
        float d2 = max(dot(d, d), 1e-12);
        falloff = 1.0 / d2;
        return d * inversesqrt(d2);
    }
    falloff = 1.0;
    return -normalize(u_lightVec[i]);
}

// Shadow-map visibility with a normal offset that grows at grazing angles (no
// acne on curved translucent surfaces) and PCF: four bilinear-compared taps at
// ±½ texel, a 3×3-texel tent for the price of four lookups. The offset, ½ + sinθ
// texels, measured against the ray-cast reference: 1 + 2 sinθ let light leak
// past grazing detail (ChineseDragon-10kv, skin1 30 mm: 3.3% against 1.6%),
// ¼ + ½ sinθ shows acne (7–13% on every scene). The taps are a loop of 4 or
// 0 trips, 0 where the light is behind: llvmpipe runs both sides of a
// branch, masked, but leaves a loop no lane is in, so a block of pixels
// facing away skips the lookups (the caller drops their result).
// A texel of the tent that sees past the point by more than the point's own
// surface can there (2 + 2 tanθ texels deeper, cosθ ≥ 0.05) does not see that
// surface: it ends before the texel. Where another texel of the tent sees an
// occluder at least as far in front (a solid in another's shadow whose edge
// lines up with the occluder's silhouette, docs/design.md §2 "Shadows"),
// such texels are left out of the mean — counted lit, they let light into
// the shadowed solid. Elsewhere (a convex terminator, whose own surface
// bulges a little in front, a penumbra on a receiver that goes on) V is the
// tent's mean as it was. The two more compares, and their projections, run
// only where the taps disagree (a tent all lit is 1 either way, all shadowed
// 0: a loop of 4 or 0 trips, as above; the projections inside it, redone per
// trip, since a block whose taps all agree then skips them).
float visibility(int i, vec3 p, vec3 n, vec3 l) {
    if (u_lightShadows[i] == 0) return 1.0;
    float cosT = clamp(dot(n, l), 0.0, 1.0);
    float sinT = sqrt(1.0 - cosT * cosT);
    vec3 q = p + n * u_shadowTexelMm[i] * (0.5 + 1.0 * sinT);
    vec4 c = u_lightViewProj[i] * vec4(q, 1.0);
    vec3 s = c.xyz / c.w * 0.5 + 0.5;
    if (any(lessThan(s.xy, vec2(0.0))) || any(greaterThan(s.xy, vec2(1.0)))) return 1.0;
    vec2 texel = 1.0 / vec2(textureSize(u_shadowMaps, 0).xy);
    float lit = 0.0;
    int taps = cosT > 0.0 ? 4 : 0;
    for (int k = 0; k < taps; ++k) {
        vec2 o = vec2((k & 1) == 0 ? -0.5 : 0.5, k < 2 ? -0.5 : 0.5) * texel;
        lit += texture(u_shadowMaps, vec4(s.xy + o, float(i), s.z - 2e-5));
    }
    float past = 0.0, near = 0.0;
    int edge = lit > 0.0 && lit < 4.0 ? 4 : 0;
    for (int k = 0; k < edge; ++k) {
        vec3 beyond = l * (u_shadowTexelMm[i] * (2.0 + 2.0 * min(sinT / max(cosT, 0.05), 20.0)));
        vec4 f = u_lightViewProj[i] * vec4(q - beyond, 1.0);
        vec4 m = u_lightViewProj[i] * vec4(q + beyond, 1.0);
        vec2 o = vec2((k & 1) == 0 ? -0.5 : 0.5, k < 2 ? -0.5 : 0.5) * texel;
        past += texture(u_shadowMaps, vec4(s.xy + o, float(i), f.z / f.w * 0.5 + 0.5));
        near += 1.0 - texture(u_shadowMaps, vec4(s.xy + o, float(i), m.z / m.w * 0.5 + 0.5));
    }
    if (near > 0.0 && past > 0.0) return past < 3.999 ? (lit - past) / (4.0 - past) : 1.0;
    return 0.25 * lit;
}

// Light i seen from p with normal n: its direction l, c = n·l and falloff;
// false when it lights the other side.
bool facing(int i, vec3 p, vec3 n, out vec3 l, out float c, out float falloff) {
    l = toLight(i, p, falloff);
    c = dot(n, l);
    return c > 0.0;
}

// E(x) of docs/design.md §2, summed over the lights, into a medium of index eta.
vec3 irradiance(vec3 p, vec3 n, float eta) {
    vec3 e = vec3(0.0);
    // A constant trip count (unrolled, so the light uniforms are read at
    // constant indices: llvmpipe gathers dynamically indexed ones per lane).
    for (int i = 0; i < MAX_LIGHTS; ++i) {
        if (i >= u_lightCount) break;
        vec3 l;
        float c, falloff;
        if (!facing(i, p, n, l, c, falloff)) continue;
        e += u_lightRgb[i] * (fresnelT(eta, c) * c * falloff * visibility(i, p, n, l));
    }
    return e;
}

// The dielectric GGX lobe (docs/design.md "Surface reflection"; its double twin is
// host/physics/ggx.h): D·G2·F(η, v·h) / (4 cosθi cosθo) with α = R², Smith's
// height-correlated G2 and the exact Fresnel reflectance at the microfacet.
float smithLambda(float alpha, float c) {
    c = clamp(c, 1e-6, 1.0);
    float tan2 = (1.0 - c * c) / (c * c);
    return 0.5 * (sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}
float ggxBrdf(float eta, float alpha, vec3 n, vec3 v, vec3 l) {
    float ci = dot(n, l), co = dot(n, v);
    if (ci <= 0.0 || co <= 0.0) return 0.0;
    vec3 h = normalize(l + v);
    float ch = max(dot(n, h), 0.0);
    float a2 = alpha * alpha;
    float t = ch * ch * (a2 - 1.0) + 1.0;
    float d = a2 / (PI * t * t);
    float g = 1.0 / (1.0 + smithLambda(alpha, ci) + smithLambda(alpha, co));
    return d * g * fresnelR(eta, dot(v, h)) / (4.0 * ci * co);
}

// The lobe's radiance towards v from the lights: Σ f·I·falloff·cosθi·V, on a
// medium of index eta.
vec3 specularRadiance(vec3 p, vec3 n, vec3 v, float alpha, float eta) {
    vec3 s = vec3(0.0);
    // A constant trip count, as in irradiance().
    for (int i = 0; i < MAX_LIGHTS; ++i) {
        if (i >= u_lightCount) break;
        vec3 l;
        float c, falloff;
        if (!facing(i, p, n, l, c, falloff)) continue;
        vec3 e = u_lightRgb[i] * (c * falloff);
        float f = ggxBrdf(eta, alpha, n, v, l);
        // Below 1e-4 of a white Lambertian surface's (1/π) the lobe is under
        // an 8-bit step wherever the object shows: skip the shadow taps, which
        // cost most of this pass.
        if (f < 1e-4 / PI) continue;
        s += f * e * visibility(i, p, n, l);
    }
    return s;
}

// The tone curve (--tone, render_options.h ToneCurve): 0 Reinhard's
// Ls/(1 + Ls); 1 the ACES filmic fit of Narkowicz (2015),
// (Ls(2.51 Ls + 0.03))/(Ls(2.43 Ls + 0.59) + 0.14) clamped to 1 (its input
// the exposed radiance × 0.6, his pre-scale, so that a mid grey lands near
// Reinhard's); 2 none: Ls clamped to [0, 1] (linear output).
uniform int u_tone;
vec3 toneCurve(vec3 ls) {
    if (u_tone == 1) {
        vec3 x = 0.6 * ls;
        return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
    }
    if (u_tone == 2) return clamp(ls, 0.0, 1.0);
    return ls / (1.0 + ls);
}

// The display (resolve.frag, radiance.frag's straight-to-display centres):
// radiance l exposed, Ls = scale · l, through the tone curve where l shows
// the object (alpha > 0), else the background's colour.
vec3 exposed(vec4 l, float scale, vec3 background) {
    return l.a > 0.0 ? toneCurve(scale * l.rgb) : background;
}

vec3 srgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

// A lat-long map's (u, v) of unit direction d in the map's frame
// (scene/environment.h latLongCoordinates): v = 0 straight up (+y), the
// centre column along −z.
vec2 latLongUv(vec3 d) {
    return vec2(atan(d.x, -d.z) / (2.0 * PI) + 0.5, acos(clamp(d.y, -1.0, 1.0)) / PI);
}

// The background (--background, render_options.h Background), as display
// colour before sRGB: 0 a dark vertical gradient over the frame's height; 1
// transparent (0, the display's alpha 0); 2 the environment map seen through
// the camera (the whole map, its sun included, × its intensity), exposed by
// u_scale and through the tone curve like the object.
uniform int u_background;
uniform mat4 u_inverseViewProj;
uniform mat3 u_backgroundToMap;
uniform float u_backgroundScale;
uniform sampler2D u_envBackground;
uniform vec2 u_frameSize;
vec3 backgroundAt(vec2 fragCoord, float scale) {
    if (u_background == 1) return vec3(0.0);
    if (u_background == 2) {
        vec2 ndc = fragCoord / u_frameSize * 2.0 - 1.0;
        vec4 near = u_inverseViewProj * vec4(ndc, -1.0, 1.0);
        vec4 far = u_inverseViewProj * vec4(ndc, 1.0, 1.0);
        vec3 d = normalize(u_backgroundToMap * (far.xyz / far.w - near.xyz / near.w));
        return toneCurve(scale * u_backgroundScale * textureLod(u_envBackground, latLongUv(d), 0.0).rgb);
    }
    return vec3(mix(0.004, 0.03, fragCoord.y / u_frameSize.y));
}

// The log-average's term of radiance l, (log(1e-12 + Y), 1) where l shows the
// object, else 0 (reduce.frag sums it).
vec4 logLuminance(vec4 l) {
    return l.a > 0.0 ? vec4(log(1e-12 + max(0.0, dot(LUMA, l.rgb))), 1.0, 0.0, 0.0) : vec4(0.0);
}
