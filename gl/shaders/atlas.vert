// Rasterises the mesh in texture space: each triangle lands on its UVs.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in float a_areaRatio;
layout(location = 4) in float a_medium;  // 1 + medium (mesh/media.h)
out vec3 v_position;
out vec3 v_normal;
flat out float v_areaRatio;
flat out float v_medium;

void main() {
    v_position = a_position;
    v_normal = a_normal;
    v_areaRatio = a_areaRatio;
    v_medium = a_medium;
    gl_Position = vec4(a_uv * 2.0 - 1.0, 0.0, 1.0);
}
