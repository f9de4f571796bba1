#version 450 core
// assemble.comp as a fragment pass (fragment_simulation.cpp): the transformed fields, two complex
// ones a texture, unpacked into the cascade's layer of the two maps the renderer samples:
//     displacement = (l Dx, h, l Dz, l dDx/dz)      slopes = (dh/dx, dh/dz, l dDx/dx, l dDz/dz)
uniform sampler2D u_fields_01;  // (h, Dx, Dz, dh/dx)
uniform sampler2D u_fields_23;  // (dh/dz, dDx/dx, dDz/dz, dDx/dz)
uniform float u_choppiness;

layout(location = 0) out vec4 displacement;
layout(location = 1) out vec4 slopes;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 a = texelFetch(u_fields_01, texel, 0);
    vec4 b = texelFetch(u_fields_23, texel, 0);
    float l = u_choppiness;
    displacement = vec4(l * a.y, a.x, l * a.z, l * b.w);
    slopes = vec4(a.w, b.x, l * b.y, l * b.z);
}
