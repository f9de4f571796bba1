#version 450 core
// A floating body's mesh, placed by its model matrix (from the world origin near the camera).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
uniform mat4 u_model, u_view_projection;
uniform vec3 u_scale;  // the mesh's scale inside u_model
out vec3 v_position, v_normal;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_position = world.xyz;
    v_normal = normalize(mat3(u_model) * (a_normal / (u_scale * u_scale)));  // R S (n / s^2) = R (n / s): a scaled box's normals
    gl_Position = u_view_projection * world;
}
