// Geometry atlas (once per mesh and resolution): the surface position and
// normal of each texel, and the surface area the texel stands for,
// (A3D/AUV)·(texel UV area), in the normal's w; the position's w is the
// texel's medium tag, 1 + medium (mesh/media.h).
in vec3 v_position;
in vec3 v_normal;
flat in float v_areaRatio;
flat in float v_medium;
uniform float u_texelArea;  // UV area of one texel: 1 / res²
layout(location = 0) out vec4 o_position;
layout(location = 1) out vec4 o_normal;

void main() {
    o_position = vec4(v_position, v_medium);
    o_normal = vec4(normalize(v_normal), v_areaRatio * u_texelArea);
}
