// The direction through texel (x, y) of a cubemap face, as the GL spec lays faces out
// (+X, -X, +Y, -Y, +Z, -Z; s and t from the table in "Cube Map Texture Selection").
vec3 cube_direction(int face, vec2 uv) {  // uv in [0, 1]
    vec2 st = uv * 2.0 - 1.0;
    vec3 d;
    if (face == 0) d = vec3(1.0, -st.y, -st.x);
    else if (face == 1) d = vec3(-1.0, -st.y, st.x);
    else if (face == 2) d = vec3(st.x, 1.0, st.y);
    else if (face == 3) d = vec3(st.x, -1.0, -st.y);
    else if (face == 4) d = vec3(st.x, -st.y, 1.0);
    else d = vec3(-st.x, -st.y, -1.0);
    return normalize(d);
}
