// How the simulation's buffers are laid out, shared by every compute pass (and ocean_simulation.cpp).
// A "line" is one row (fixed z) or column (fixed x) of one N x N complex field. The buffers hold
// u_layer_count cascades x 4 packed complex fields x N x N values, row (z) major:
//     index = ((cascade * 4 + field) * N + j) * N + i
uniform int u_n;            // N: modes per side
uniform int u_layer_count;  // cascades (1 in step05)

int field_base(int cascade, int field) { return (cascade * 4 + field) * u_n * u_n; }

vec2 complex_multiply(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
