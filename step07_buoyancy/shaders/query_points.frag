#version 450 core
// A query's dot: a bright yellow, far above the sea's radiance, so it reads against glitter.
out vec4 out_colour;

void main() { out_colour = vec4(4.0, 3.2, 0.4, 1.0); }
