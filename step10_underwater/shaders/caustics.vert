#version 450 core
// Caustics, the cells drawn as triangles (caustic_cells.glsl): each vertex is a ray, placed where
// it landed. A triangle is drawn only if its cell is: whether it is comes from the triangle's last
// vertex (GL's provoking vertex, the only one ES has), ray (i, j + 1), the last of both triangles
// of cell (i, j) and of no other cell's.
#include "caustic_cells.glsl"

out vec2 v_source;        // where the ray crossed the level plane, and
out vec2 v_landed;        // where it reached the seabed (metres)
out float v_transmitted;  // the share of its light the surface let through
flat out int v_cell_drawn;

void main() {
    int i = gl_VertexID % u_grid_side, j = gl_VertexID / u_grid_side;
    Ray ray = ray_at(i, j);
    v_source = ray.source;
    v_landed = ray.landed;
    v_transmitted = ray.transmitted;
    v_cell_drawn = int(j > 0 && i + 1 < u_grid_side && cell_at(i, j - 1).as_triangles);
    gl_Position = seabed_clip(ray.landed);
}
