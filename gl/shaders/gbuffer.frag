// Camera G-buffer: world position (w = coverage) and normal.
in vec3 v_position;
in vec3 v_normal;
layout(location = 0) out vec4 o_position;
layout(location = 1) out vec4 o_normal;

void main() {
    o_position = vec4(v_position, 1.0);
    o_normal = vec4(normalize(v_normal), 1.0);
}
