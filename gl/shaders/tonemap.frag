// The display image (docs/design.md "The composite") from the radiance of u_aa × u_aa
// samples per pixel: each sample exposed, Ls = u_scale · L (2^EV, or key/L_avg
// with --auto-exposure), through Reinhard's curve Ls/(1 + Ls), the samples
// averaged (a box filter; after the curve, so that a highlight does not flood
// its silhouette pixel), then sRGB encoding.
uniform sampler2D u_radiance;  // alpha: 1 where a sample shows the object
uniform int u_aa;
uniform float u_scale;
layout(location = 0) out vec4 o_color;

vec3 srgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    // Background: a dark vertical gradient.
    float t = gl_FragCoord.y / float(textureSize(u_radiance, 0).y / u_aa);
    vec3 background = vec3(mix(0.004, 0.03, t));
    vec3 sum = vec3(0.0);
    for (int j = 0; j < u_aa; ++j)
        for (int i = 0; i < u_aa; ++i) {
            vec4 l = texelFetch(u_radiance, px * u_aa + ivec2(i, j), 0);
            vec3 ls = u_scale * l.rgb;
            sum += l.a > 0.0 ? ls / (1.0 + ls) : background;
        }
    o_color = vec4(srgb(sum / float(u_aa * u_aa)), 1.0);
}
