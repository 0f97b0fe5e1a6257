// The display image (docs/design.md "The composite"): each sample exposed,
// Ls = u_scale · L (2^EV, or key/L_avg with --auto-exposure), through
// Reinhard's curve Ls/(1 + Ls); in a supersampled pixel the u_aa × u_aa
// samples averaged (a box filter; after the curve, so that a highlight does
// not flood its silhouette pixel), elsewhere the centre's; then sRGB.
uniform sampler2D u_centre;   // alpha: 1 where the sample shows the object
uniform sampler2D u_samples;  // u_aa × the size; read where u_edges is set
uniform sampler2D u_edges;
uniform int u_aa;
uniform float u_scale;
layout(location = 0) out vec4 o_color;

vec3 srgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

// Background: a dark vertical gradient.
vec3 exposed(vec4 l, vec3 background) {
    vec3 ls = u_scale * l.rgb;
    return l.a > 0.0 ? ls / (1.0 + ls) : background;
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 background = vec3(mix(0.004, 0.03, gl_FragCoord.y / float(textureSize(u_centre, 0).y)));
    if (texelFetch(u_edges, px, 0).r == 0.0) {
        o_color = vec4(srgb(exposed(texelFetch(u_centre, px, 0), background)), 1.0);
        return;
    }
    vec3 sum = vec3(0.0);
    for (int j = 0; j < u_aa; ++j)
        for (int i = 0; i < u_aa; ++i)
            sum += exposed(texelFetch(u_samples, px * u_aa + ivec2(i, j), 0), background);
    o_color = vec4(srgb(sum / float(u_aa * u_aa)), 1.0);
}
