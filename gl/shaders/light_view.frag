// The light's view: depth (the shadow map) plus the flux that lands in each
// texel (docs/design.md §2) and the surface position, for the light-view
// methods.
// Point light: flux = I · Ft · dω(texel) — the cosine and 1/d² cancel against
// the area the texel's solid angle covers. Directional: flux = I · Ft · texel area.
in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
flat in float v_medium;  // the flux's a: 1 + medium, 0 where no surface
uniform int u_light;
uniform float u_tanHalf;     // point: tan of half the field of view
uniform float u_texelAreaMm; // directional: texel area (mm²)
uniform vec2 u_resolution;
layout(location = 0) out vec4 o_flux;
layout(location = 1) out vec4 o_position;

void main() {
    vec3 n = shadingNormal(normalize(v_normal), v_uv);
    float falloff;
    vec3 l = toLight(u_light, v_position, falloff);
    float c = dot(n, l);
    float measure = u_texelAreaMm;
    if (u_lightType[u_light] == 0) {
        vec2 t = ((gl_FragCoord.xy / u_resolution) * 2.0 - 1.0) * u_tanHalf;
        float step = 2.0 * u_tanHalf / u_resolution.x;
        measure = step * step / pow(1.0 + dot(t, t), 1.5);
    }
    vec3 flux = c > 0.0 ? u_lightRgb[u_light] * (fresnelT(mediumOf(v_medium).r, c) * measure) : vec3(0.0);
    o_flux = vec4(flux * albedoFactor(v_uv), v_medium);
    o_position = vec4(v_position, length(u_lightVec[u_light] - v_position));
}
