// The frame's pixels from the composite's samples (docs/design.md "The
// composite"). A pixel's radiance is its centre's sample, or in a
// supersampled pixel the mean over its u_aa × u_aa samples that show the
// object, alpha the fraction that do (0: none); location 1 holds its log
// luminance for the log-average, (log(1e-12 + Y), 1) where alpha > 0, else 0
// (reduce.frag sums it).
//
// Location 0: that radiance; with TSIS_TONE_MAP, the display colour instead:
// each sample exposed, Ls = u_scale · L (2^EV, or key/L_avg with
// --auto-exposure), through Reinhard's curve Ls/(1 + Ls), in a supersampled
// pixel the samples averaged (a box filter; after the curve, so that a
// highlight does not flood its silhouette pixel), then sRGB.
//
// Three variants: a full-screen pass of the centres at the covered pixels
// (CompositePass: by the G-buffer's depth), with TSIS_BACKGROUND one at the
// others (the tone map's background; the resolve leaves them 0), then, with
// TSIS_RESOLVE_EDGES, the supersampled pixels over them — llvmpipe runs both
// sides of a branch, so one pass with all three would average samples and
// tone-map at every pixel. The last is packed as the samples are: a
// full-screen pass over one texel per supersampled pixel, its slot, that
// stores its two results at its pixel of u_outColor and u_outLogLuminance
// (llvmpipe shades whole 4×4 blocks: a point per pixel paid for sixteen).
uniform sampler2D u_centre;   // alpha: 1 where the sample shows the object
// The supersampled pixels' samples, packed (radiance.frag): a pixel's u_aa ×
// u_aa block at its slot.
uniform sampler2D u_samples;
uniform int u_aa;
#ifdef TSIS_RESOLVE_EDGES
uniform sampler2D u_edgePixels;  // pixel e's (x, y) at slot (e mod width, e div width)
#ifdef TSIS_TONE_MAP
layout(rgba8) uniform writeonly image2D u_outColor;
#else
layout(rgba32f) uniform writeonly image2D u_outColor;
#endif
layout(rg32f) uniform writeonly image2D u_outLogLuminance;
#else
layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_logLuminance;
#endif

#ifdef TSIS_TONE_MAP
uniform float u_scale;
#endif

#ifdef TSIS_BACKGROUND
void main() {
    o_color = vec4(srgb(backgroundAt(gl_FragCoord.xy, u_scale)), u_background == 1 ? 0.0 : 1.0);
    o_logLuminance = vec4(0.0);
}
#else
void main() {
#ifdef TSIS_RESOLVE_EDGES
    ivec2 slot = ivec2(gl_FragCoord.xy);
    ivec2 px = ivec2(texelFetch(u_edgePixels, slot, 0).xy);
#else
    ivec2 px = ivec2(gl_FragCoord.xy);
#endif
#ifdef TSIS_TONE_MAP
    vec3 background = backgroundAt(vec2(px) + 0.5, u_scale);
    vec3 display = vec3(0.0);
#endif
    vec4 radiance;
#ifndef TSIS_RESOLVE_EDGES
    radiance = texelFetch(u_centre, px, 0);
#ifdef TSIS_TONE_MAP
    display = exposed(radiance, u_scale, background);
#endif
#else
    {
        vec3 sum = vec3(0.0);
        float covered = 0.0;
        for (int j = 0; j < u_aa; ++j)
            for (int i = 0; i < u_aa; ++i) {
                vec4 l = texelFetch(u_samples, slot * u_aa + ivec2(i, j), 0);
                sum += l.rgb * l.a;
                covered += l.a;
#ifdef TSIS_TONE_MAP
                display += exposed(l, u_scale, background);
#endif
            }
        radiance =
            covered > 0.0 ? vec4(sum / covered, covered / float(u_aa * u_aa)) : vec4(0.0);
#ifdef TSIS_TONE_MAP
        display /= float(u_aa * u_aa);
#endif
    }
#endif
    vec4 logL = logLuminance(radiance);
#ifdef TSIS_TONE_MAP
    // Transparent: alpha the fraction of the pixel's samples that show the
    // object, the colour theirs alone (straight alpha, as PNG stores it).
    float alpha = u_background == 1 ? radiance.a : 1.0;
    if (u_background == 1) display = alpha > 0.0 ? display / alpha : vec3(0.0);
    vec4 color = vec4(srgb(display), alpha);
#else
    vec4 color = radiance;
#endif
#ifdef TSIS_RESOLVE_EDGES
    // The slots past the list repeat its last pixel: the same values again.
    imageStore(u_outColor, px, color);
    imageStore(u_outLogLuminance, px, logL);
#else
    o_color = color;
    o_logLuminance = logL;
#endif
}
#endif
