// Flux per atlas texel = E(x) · (A3D/AUV) · texel UV area (DESIGN §2), so the
// atlas sums to the total flux the object receives. Also position and normal.
in vec3 v_position;
in vec3 v_normal;
flat in float v_areaRatio;
uniform float u_texelArea;  // UV area of one texel: 1 / res²
layout(location = 0) out vec4 o_flux;
layout(location = 1) out vec4 o_position;
layout(location = 2) out vec4 o_normal;

void main() {
    vec3 n = normalize(v_normal);
    o_flux = vec4(irradiance(v_position, n) * (v_areaRatio * u_texelArea), 1.0);
    o_position = vec4(v_position, 1.0);
    o_normal = vec4(n, 1.0);
}
