#version 450 core
// Patches of the sea around the camera: each control point is a patch corner, on a grid that
// follows the camera in whole patch steps (so the water does not swim under it).
layout(location = 0) in vec2 a_corner;  // metres, grid centred on the origin

uniform vec2 u_grid_offset;  // the camera's x, z snapped to the patch size

out vec2 tc_rest_xz;

void main() { tc_rest_xz = a_corner + u_grid_offset; }
