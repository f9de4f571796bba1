#version 450 core
// The answered height queries, as dots where each says the water is (from the world origin near
// the camera): on the surface if the inversion is right, above or under it on steep waves if not.
layout(location = 0) in vec3 a_position;
uniform mat4 u_view_projection;

void main() {
    gl_Position = u_view_projection * vec4(a_position, 1.0);
    gl_PointSize = 3.0;
}
