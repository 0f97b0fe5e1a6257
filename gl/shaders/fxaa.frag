// --aa-method fxaa: the display image antialiased after the fact, in the
// manner of Lottes' FXAA (2009): where the luma's local contrast marks an
// edge, find the edge's orientation and its two ends along it, and sample
// the image bilinearly that far across the edge as the pixel sits from the
// nearer end's middle (a long, shallow step blends most at its ends); thin
// features get a blend from their 3×3 contrast (the sub-pixel term).
// u_display is sRGB in RGBA8 (alpha: the coverage, or 1), read through a
// bilinear sampler.
//
// One pass over the edge pixels only (CompositePass::fxaa), packed as
// --aa's samples: edge e at its slot (e mod width, e div width) of
// u_edgePixels' size, its colour stored at its pixel of u_out (the display's
// copy). llvmpipe shades whole 4×4 blocks: a point per pixel running the
// search paid it sixteen times.
uniform sampler2D u_display;
layout(rgba8) uniform writeonly image2D u_out;
uniform sampler2D u_edgePixels;  // pixel e's (x, y) at texel (e mod width, e div width)

// Below this local contrast (absolute, or of the brightest luma) nothing is done.
const float kEdgeMin = 1.0 / 24.0;
const float kEdgeRelative = 1.0 / 8.0;
// How far the sub-pixel term may move a sample (0: off, 1: a whole texel).
const float kSubpixel = 0.75;
// The search along the edge: steps of growing size, in texels.
const int kSteps = 6;
const float kStep[kSteps] = float[](1.0, 1.5, 2.0, 2.0, 4.0, 8.0);

float lumaOf(vec3 c) {
    return dot(c, vec3(0.299, 0.587, 0.114));
}

float lumaAt(vec2 uv) {
    return lumaOf(textureLod(u_display, uv, 0.0).rgb);
}

// The bilinear read of the display at uv with its colour weighted by alpha
// (straight alpha, --background transparent: an uncovered texel's colour is
// none of the pixel's); with every alpha 1, the plain bilinear read.
vec4 straightAlphaAt(vec2 uv) {
    vec2 size = vec2(textureSize(u_display, 0));
    vec2 p = uv * size - 0.5;
    vec2 f = fract(p);
    ivec2 base = ivec2(floor(p));
    vec3 rgb = vec3(0.0);
    float alpha = 0.0;
    for (int k = 0; k < 4; ++k) {
        ivec2 o = ivec2(k & 1, k >> 1);
        vec4 t = texelFetch(u_display, clamp(base + o, ivec2(0), ivec2(size) - 1), 0);
        float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
        rgb += w * t.a * t.rgb;
        alpha += w * t.a;
    }
    return alpha > 0.0 ? vec4(rgb / alpha, alpha) : textureLod(u_display, uv, 0.0);
}

void main() {
    vec2 texel = 1.0 / vec2(textureSize(u_display, 0));
    ivec2 pixel = ivec2(texelFetch(u_edgePixels, ivec2(gl_FragCoord.xy), 0).xy);
    vec2 uv = (vec2(pixel) + 0.5) * texel;
    vec4 centre = textureLod(u_display, uv, 0.0);
    float lC = lumaOf(centre.rgb);
    float lN = lumaAt(uv + vec2(0.0, texel.y)), lS = lumaAt(uv - vec2(0.0, texel.y));
    float lE = lumaAt(uv + vec2(texel.x, 0.0)), lW = lumaAt(uv - vec2(texel.x, 0.0));
    float lo = min(lC, min(min(lN, lS), min(lE, lW)));
    float hi = max(lC, max(max(lN, lS), max(lE, lW)));
    float range = hi - lo;
    if (range < max(kEdgeMin, hi * kEdgeRelative)) return;  // the copy's is right
    float lNE = lumaAt(uv + texel), lSW = lumaAt(uv - texel);
    float lNW = lumaAt(uv + vec2(-texel.x, texel.y)), lSE = lumaAt(uv + vec2(texel.x, -texel.y));
    // The edge runs along x where the luma changes most across y.
    float acrossY = 2.0 * abs(lN + lS - 2.0 * lC) + abs(lNE + lSE - 2.0 * lE) +
                    abs(lNW + lSW - 2.0 * lW);
    float acrossX = 2.0 * abs(lE + lW - 2.0 * lC) + abs(lNE + lNW - 2.0 * lN) +
                    abs(lSE + lSW - 2.0 * lS);
    bool alongX = acrossY >= acrossX;
    // The side of the pixel the edge is on: its neighbour of the larger step.
    float lBelow = alongX ? lS : lW, lAbove = alongX ? lN : lE;
    float stepBelow = abs(lBelow - lC), stepAbove = abs(lAbove - lC);
    float across = alongX ? texel.y : texel.x;
    float lEdge;
    if (stepBelow >= stepAbove) {
        across = -across;
        lEdge = 0.5 * (lBelow + lC);
    } else {
        lEdge = 0.5 * (lAbove + lC);
    }
    float threshold = 0.25 * max(stepBelow, stepAbove);
    // Walk both ways along the edge's middle until the luma leaves it.
    vec2 onEdge = uv + (alongX ? vec2(0.0, 0.5 * across) : vec2(0.5 * across, 0.0));
    vec2 along = alongX ? vec2(texel.x, 0.0) : vec2(0.0, texel.y);
    vec2 uvP = onEdge + along, uvN = onEdge - along;
    float dP = lumaAt(uvP) - lEdge, dN = lumaAt(uvN) - lEdge;
    bool endP = abs(dP) >= threshold, endN = abs(dN) >= threshold;
    for (int i = 1; i < kSteps && !(endP && endN); ++i) {
        if (!endP) {
            uvP += along * kStep[i];
            dP = lumaAt(uvP) - lEdge;
            endP = abs(dP) >= threshold;
        }
        if (!endN) {
            uvN -= along * kStep[i];
            dN = lumaAt(uvN) - lEdge;
            endN = abs(dN) >= threshold;
        }
    }
    float distP = alongX ? uvP.x - uv.x : uvP.y - uv.y;
    float distN = alongX ? uv.x - uvN.x : uv.y - uvN.y;
    bool nearerN = distN < distP;
    // Blend only towards an end where the step goes the other way from the
    // pixel's (the pixel is on the short side of the step there).
    bool centreBelowEdge = lC < lEdge;
    bool blends = ((nearerN ? dN : dP) < 0.0) != centreBelowEdge;
    float offset = blends ? 0.5 - min(distN, distP) / (distN + distP) : 0.0;
    // Sub-pixel: a pixel unlike its 3×3 neighbourhood's mean (a thin line).
    float mean = (2.0 * (lN + lS + lE + lW) + lNE + lNW + lSE + lSW) / 12.0;
    float sub = smoothstep(0.0, 1.0, clamp(abs(mean - lC) / range, 0.0, 1.0));
    offset = max(offset, sub * sub * kSubpixel);
    vec2 at = uv + (alongX ? vec2(0.0, offset * across) : vec2(offset * across, 0.0));
    imageStore(u_out, pixel, straightAlphaAt(at));
}
