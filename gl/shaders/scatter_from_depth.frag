// The single-scattering term's view of a light (render/single_scatter.h)
// made from the light's shadow map, not from a draw of the mesh (llvmpipe's
// cost of a view is the mesh's set-up, not its texels): at each texel the
// surface point unprojected from the depth of the shadow texel under its
// centre, and the facet's normal from the neighbouring depths, one-sided
// towards the neighbour whose depth continues the surface's (a silhouette
// or an occluding edge on the other side); w = u_tag. (0) where the map
// holds no surface. The cross product of the steps along the view's x and y
// faces the light (clip space is left-handed): the map's surface is the one
// the light sees, so its normal is never turned away, as a drawn view's
// would be on a back face: only closed, outward meshes are made this way.
uniform sampler2DArray u_depth;  // raw depth: a sampler without the compare
uniform int u_layer;
uniform mat4 u_lightToWorld;
uniform float u_tag;
uniform int u_resolution;  // this view's texels a side
layout(location = 0) out vec4 o_position;
layout(location = 1) out vec4 o_normal;

vec2 g_size;

vec3 unproject(vec2 t, float z) {
    vec4 p = u_lightToWorld * vec4((t + 0.5) / g_size * 2.0 - 1.0, z * 2.0 - 1.0, 1.0);
    return p.xyz / p.w;
}

// The step to the neighbour at t ± d along the surface: towards the side
// whose depth is nearer the centre's, one that holds a surface (a select,
// not a branch: llvmpipe would run both).
vec3 tangent(vec2 t, vec2 d, float z, float zp, float zm, vec3 p) {
    float side = zp < 1.0 && (!(zm < 1.0) || abs(zp - z) <= abs(z - zm)) ? 1.0 : -1.0;
    return side * (unproject(t + side * d, side > 0.0 ? zp : zm) - p);
}

void main() {
    g_size = vec2(textureSize(u_depth, 0).xy);
    vec2 t = floor(gl_FragCoord.xy * g_size / float(u_resolution));
    // Texel t and its four neighbours in two gathers: (t, t + 1) and (t - 1, t).
    vec4 up = textureGather(u_depth, vec3((t + 1.0) / g_size, float(u_layer)));
    vec4 down = textureGather(u_depth, vec3(t / g_size, float(u_layer)));
    float z = up.w;
    bool surface = z < 1.0 && (up.z < 1.0 || down.x < 1.0) && (up.x < 1.0 || down.z < 1.0);
    vec3 p = unproject(t, z);
    vec3 n = normalize(cross(tangent(t, vec2(1.0, 0.0), z, up.z, down.x, p),
                             tangent(t, vec2(0.0, 1.0), z, up.x, down.z, p)));
    o_position = surface ? vec4(p, 1.0) : vec4(0.0);
    o_normal = surface ? vec4(n, u_tag) : vec4(0.0);
}
