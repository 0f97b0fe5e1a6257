// The floor of a pass on this GL (bench_frame --gl-floors): the same targets
// written with constants, so what is left of the pass' time is its shading.
layout(location = 0) out vec4 o_0;
layout(location = 1) out vec4 o_1;

void main() {
    o_0 = vec4(1.0);
    o_1 = vec4(0.5);
}
