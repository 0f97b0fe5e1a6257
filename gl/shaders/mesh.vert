// Shared by the light-view and camera passes: world position and normal out.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;  // atlas coordinates
layout(location = 4) in float a_medium;  // 1 + medium (mesh/media.h)
uniform mat4 u_viewProj;
out vec3 v_position;
out vec3 v_normal;
out vec2 v_uv;
flat out float v_medium;

void main() {
    v_position = a_position;
    v_normal = a_normal;
    v_uv = a_uv;
    v_medium = a_medium;
    gl_Position = u_viewProj * vec4(a_position, 1.0);
}
