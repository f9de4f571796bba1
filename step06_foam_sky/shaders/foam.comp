#version 450 core
// Chapter 5.3 (foam.hpp is the CPU reference): in each cascade's texel, foam decays by
// exp(-rate dt) and grows where the Jacobian falls below the threshold, at a rate times dt.
layout(local_size_x = 8, local_size_y = 8) in;
#include "step05_fft/shaders/ocean_maps.glsl"

layout(r32f, binding = 0) uniform image2DArray u_foam_image;

uniform float u_dt;
uniform float u_threshold;
uniform float u_injection;
uniform float u_cascade_weight[4];  // the short-wave cascades fold in ripples, not whitecaps: less foam
uniform float u_decay_rate;
uniform int u_n;
uniform int u_layer_count;
uniform bool u_warm_start;  // a new foam texture: start from the steady state of this J

void main() {
    ivec3 id = ivec3(gl_GlobalInvocationID);
    if (id.x >= u_n || id.y >= u_n || id.z >= u_layer_count) return;
    vec4 displacement = texelFetch(u_displacement, id, 0);
    vec4 slopes = texelFetch(u_slopes, id, 0);
    float j = jacobian(displacement, slopes);
    float foam = imageLoad(u_foam_image, id).r;
    float injection = u_injection * u_cascade_weight[id.z];
    if (u_warm_start)  // where injection and decay balance if J stayed as it is
        foam = injection * max(0.0, u_threshold - j) / max(u_decay_rate, 0.1);
    else
        foam = foam * exp(-u_decay_rate * u_dt) + injection * max(0.0, u_threshold - j) * u_dt;
    imageStore(u_foam_image, id, vec4(clamp(foam, 0.0, 1.0)));
}
