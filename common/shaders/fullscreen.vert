#version 450 core
// One triangle that covers the screen (draw 3 vertices, no buffers): corners at
// (-1,-1), (3,-1), (-1,3) in clip space; v_uv is (0,0) at the bottom left, (1,1) at the top right.
out vec2 v_uv;

void main() {
    vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    v_uv = corner;
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
