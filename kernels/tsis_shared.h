/* Structs and constants read by both the host (C++) and the OpenCL kernels.
 * Defined once here; kernels get it inlined at build time (cmake/Embed.cmake),
 * the host includes it directly. Plain float fields only, so the layout is the
 * same on both sides without packing pragmas. */
#ifndef TSIS_SHARED_H
#define TSIS_SHARED_H

#ifndef __OPENCL_VERSION__
#include <cstdint>
typedef uint32_t tsis_uint;
#else
typedef uint tsis_uint;
#endif

/* Layout checks for the structs below and those of the other shared headers:
 * the same sizes and offsets are asserted by the host's compiler and by the
 * kernel compiler (a negative array size fails an OpenCL build), so the two
 * sides cannot drift apart. */
#ifdef __OPENCL_VERSION__
#define TSIS_LAYOUT(name, cond) typedef char tsis_layout_##name[(cond) ? 1 : -1]
#else
#define TSIS_LAYOUT(name, cond) static_assert(cond, "layout of " #name)
#endif
#define TSIS_CHECK_SIZE(T, n) TSIS_LAYOUT(sizeof_##T, sizeof(T) == (n))
#define TSIS_CHECK_OFFSET(T, f, n) TSIS_LAYOUT(offsetof_##T##_##f, __builtin_offsetof(T, f) == (n))

/* One importance sample of the flux atlas: where it is, and its estimator
 * weight per channel w_c = Phi_i(c) / (N p_i), with p_i = Y(Phi_i) / sum Y.
 * B(xo) = sum_i w_i * Rd(|xo - x_i|). */
typedef struct {
    float px, py, pz;
    float texel; /* atlas texel index (as float, exact below 2^24) for debugging views */
    float wr, wg, wb;
    float medium; /* its medium's tag, 1 + medium (mesh/media.h): it lights only that medium */
} TsisSample;
TSIS_CHECK_SIZE(TsisSample, 32);
TSIS_CHECK_OFFSET(TsisSample, px, 0);
TSIS_CHECK_OFFSET(TsisSample, py, 4);
TSIS_CHECK_OFFSET(TsisSample, pz, 8);
TSIS_CHECK_OFFSET(TsisSample, texel, 12);
TSIS_CHECK_OFFSET(TsisSample, wr, 16);
TSIS_CHECK_OFFSET(TsisSample, wg, 20);
TSIS_CHECK_OFFSET(TsisSample, wb, 24);
TSIS_CHECK_OFFSET(TsisSample, medium, 28);

/* A radially symmetric profile f(r) (Rd, Rd*Wl, Rd*Wg) tabulated per channel at
 * TSIS_TABLE_SIZE points r_k = k * r_max / (TSIS_TABLE_SIZE - 1), stored as
 * float4 (r, g, b, 0); linear interpolation, zero beyond r_max. */
#define TSIS_TABLE_SIZE 8192

typedef struct {
    float r_max;
    float inv_step; /* (TSIS_TABLE_SIZE - 1) / r_max */
    tsis_uint size;
    tsis_uint pad;
} TsisTableInfo;
TSIS_CHECK_SIZE(TsisTableInfo, 16);
TSIS_CHECK_OFFSET(TsisTableInfo, r_max, 0);
TSIS_CHECK_OFFSET(TsisTableInfo, inv_step, 4);
TSIS_CHECK_OFFSET(TsisTableInfo, size, 8);
TSIS_CHECK_OFFSET(TsisTableInfo, pad, 12);

/* A node of the flux tree (kernels/flux_tree.cl, --method pyramid): atlas
 * texels close in 3D summed -- flux sum E*A per channel (fr, fg, fb) and
 * surface area (mm^2) -- and stood in for by their flux-weighted position
 * (px, py, pz); every texel lies within `radius` mm of that position.
 * area = 0: no covered texel. */
typedef struct {
    float fr, fg, fb, area;
    float px, py, pz, radius;
} TsisFluxNode;
TSIS_CHECK_SIZE(TsisFluxNode, 32);
TSIS_CHECK_OFFSET(TsisFluxNode, fr, 0);
TSIS_CHECK_OFFSET(TsisFluxNode, fg, 4);
TSIS_CHECK_OFFSET(TsisFluxNode, fb, 8);
TSIS_CHECK_OFFSET(TsisFluxNode, area, 12);
TSIS_CHECK_OFFSET(TsisFluxNode, px, 16);
TSIS_CHECK_OFFSET(TsisFluxNode, py, 20);
TSIS_CHECK_OFFSET(TsisFluxNode, pz, 24);
TSIS_CHECK_OFFSET(TsisFluxNode, radius, 28);

/* A pixel the pyramid interpolates (render/sparse_pixels.h): its packed
 * index and its grid cell's four corners' (x0 y0, x1 y0, x0 y1, x1 y1),
 * which are evaluated, with their bilinear weights. */
typedef struct {
    int point;
    int corners[4];
    float weights[4];
} TsisInterpolatedPixel;
TSIS_CHECK_SIZE(TsisInterpolatedPixel, 36);
TSIS_CHECK_OFFSET(TsisInterpolatedPixel, point, 0);
TSIS_CHECK_OFFSET(TsisInterpolatedPixel, corners, 4);
TSIS_CHECK_OFFSET(TsisInterpolatedPixel, weights, 20);

/* Depth of the flux tree below its root, at most (21 bits of Morton code an
 * axis in steps of 3, plus the splits of texels that share a code, plus the
 * splits by medium: 8 levels for up to 8^8 media): bounds the descent's
 * stack. */
#define TSIS_FLUX_TREE_MAX_DEPTH 36

/* The most lights a scene may have: the one definition the host
 * (kMaxLights), the kernels and, through ShaderProgram (MAX_LIGHTS), the GLSL
 * shaders read. */
#define TSIS_MAX_LIGHTS 8
/* Work-items summing one patch of the object transport (patch_flux.cl). */
#define TSIS_PATCH_GROUP 64
/* Of a patch's texels, this many give the light's direction (at most
 * TSIS_PATCH_GROUP). */
#define TSIS_PATCH_DIRECTION_SAMPLES 32
/* The object transport's walks enter with sin²θ of the refracted direction
 * uniform over the refracted cone, [0, 1/η²] (host/volumetric/
 * patch_transfer.cpp); the fit's slope in it is about its mean, 1/(2η²),
 * which the frame's patch sums subtract (patch_flux.cl). */
#define TSIS_ENTRY_TOP_SIN2(eta) ((1.0f / (eta)) * (1.0f / (eta)))
#define TSIS_ENTRY_MEAN_SIN2(eta) (0.5f / ((eta) * (eta)))

/* Luminance weights (Rec. 709) used for importance: Y(Phi). */
#define TSIS_LUMA_R 0.2126f
#define TSIS_LUMA_G 0.7152f
#define TSIS_LUMA_B 0.0722f
#define TSIS_LUMINANCE(r, g, b) (TSIS_LUMA_R * (r) + TSIS_LUMA_G * (g) + TSIS_LUMA_B * (b))

/* One tap of tsm's fixed filter pattern, in units of the filter radius R:
 * offset (x, y), the footprint it stands for (area / R^2) and its ring (the
 * ring's table of Rd averaged over the footprint's annulus). */
typedef struct {
    float x, y;
    float area;
    float ring;
} TsisTsmTap;
TSIS_CHECK_SIZE(TsisTsmTap, 16);
TSIS_CHECK_OFFSET(TsisTsmTap, x, 0);
TSIS_CHECK_OFFSET(TsisTsmTap, y, 4);
TSIS_CHECK_OFFSET(TsisTsmTap, area, 8);
TSIS_CHECK_OFFSET(TsisTsmTap, ring, 12);

/* The camera for image-space sampling (lss). */
typedef struct {
    float ex, ey, ez;  /* eye (mm) */
    float pixel_angle; /* 2 tan(fovY / 2) / height: a pixel's size per mm of depth */
    float fx, fy, fz;  /* unit view direction */
    float min_cos;     /* clamp of |n . view| in a pixel's surface area */
} TsisCamera;
TSIS_CHECK_SIZE(TsisCamera, 32);
TSIS_CHECK_OFFSET(TsisCamera, ex, 0);
TSIS_CHECK_OFFSET(TsisCamera, ey, 4);
TSIS_CHECK_OFFSET(TsisCamera, ez, 8);
TSIS_CHECK_OFFSET(TsisCamera, pixel_angle, 12);
TSIS_CHECK_OFFSET(TsisCamera, fx, 16);
TSIS_CHECK_OFFSET(TsisCamera, fy, 20);
TSIS_CHECK_OFFSET(TsisCamera, fz, 24);
TSIS_CHECK_OFFSET(TsisCamera, min_cos, 28);

#endif /* TSIS_SHARED_H */
