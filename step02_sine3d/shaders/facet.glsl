// The flat facet shading's normal (waves.hpp's facet_normal is the CPU reference): two vectors
// in a triangle's plane, here the screen-space derivatives of the world position (one-pixel
// steps, not the triangle's edges), crossed, and turned to face up: a normal is the cross product
// of two tangents of the surface, here measured across a pixel rather than taken from the waves'
// derivatives, so each triangle is flat.
vec3 facet_normal(vec3 along_x, vec3 along_y) {
    vec3 n = normalize(cross(along_x, along_y));
    return n.y < 0.0 ? -n : n;
}
