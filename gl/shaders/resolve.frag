// The radiance at the frame's pixels: the centre's sample, or in a
// supersampled pixel the mean over its u_aa × u_aa samples that show the
// object; alpha = the fraction that do (0: none).
uniform sampler2D u_centre;
uniform sampler2D u_samples;
uniform sampler2D u_edges;
uniform int u_aa;
layout(location = 0) out vec4 o_radiance;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    if (texelFetch(u_edges, px, 0).r == 0.0) {
        o_radiance = texelFetch(u_centre, px, 0);
        return;
    }
    vec3 sum = vec3(0.0);
    float covered = 0.0;
    for (int j = 0; j < u_aa; ++j)
        for (int i = 0; i < u_aa; ++i) {
            vec4 l = texelFetch(u_samples, px * u_aa + ivec2(i, j), 0);
            sum += l.rgb * l.a;
            covered += l.a;
        }
    o_radiance = covered > 0.0 ? vec4(sum / covered, covered / float(u_aa * u_aa)) : vec4(0.0);
}
