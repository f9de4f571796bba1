#version 450 core
// Caustics, the cells too small to draw as triangles (caustic_cells.glsl), one point each: a
// point two texels wide at the cell's landing, whose four texels share its light.
#include "caustic_cells.glsl"

out float v_irradiance;  // the cell's light over one texel's area, relative to a flat sea's

uniform float u_flat_transmitted;

void main() {
    int i = gl_VertexID % u_grid_side, j = gl_VertexID / u_grid_side;
    gl_PointSize = 2.0;
    v_irradiance = 0.0;
    gl_Position = vec4(2.0, 2.0, 0.0, 1.0);  // outside: no point
    if (i + 1 >= u_grid_side || j + 1 >= u_grid_side) return;  // the last row and column start no cell
    Cell cell = cell_at(i, j);
    if (cell.as_triangles) return;
    v_irradiance = cell.light / u_texel_area / u_flat_transmitted;
    gl_Position = seabed_clip(cell.centre);
}
