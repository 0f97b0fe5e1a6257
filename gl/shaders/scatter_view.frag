// The surface the light sees, for the single-scattering term
// (render/single_scatter.h): its position and shading normal, w = the
// medium tag (1 + medium; 0, the clear colour, where no surface).
in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
flat in float v_medium;
layout(location = 0) out vec4 o_position;
layout(location = 1) out vec4 o_normal;

void main() {
    o_position = vec4(v_position, 1.0);
    o_normal = vec4(shadingNormal(normalize(v_normal), v_uv), v_medium);
}
