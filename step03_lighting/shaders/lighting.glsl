// Chapter 2's lighting (lighting.hpp is the CPU reference): ambient + Lambert diffuse tinted by
// the water colour + Blinn-Phong specular with the normalised halfway vector.
uniform vec3 u_to_sun;        // L, unit, towards the sun
uniform vec3 u_sun_color;
uniform vec3 u_water_color;
uniform vec3 u_ambient_color;
uniform float u_shininess;

struct LightTerms {
    vec3 ambient, diffuse, specular;
};

LightTerms light_terms(vec3 normal, vec3 to_eye) {
    float n_dot_l = dot(normal, u_to_sun);
    vec3 halfway = normalize(to_eye + u_to_sun);
    float blinn = n_dot_l > 0.0 ? pow(max(dot(normal, halfway), 0.0), u_shininess) : 0.0;
    LightTerms t;
    t.ambient = u_ambient_color;
    t.diffuse = u_water_color * u_sun_color * max(n_dot_l, 0.0);
    t.specular = u_sun_color * blinn;
    return t;
}

// Phong's glint, the step's specular=phong (lighting.hpp's phong_specular is the CPU reference): the
// sun mirrored about the normal, compared with the eye, its lobe as wide as Blinn-Phong's at
// u_shininess for an eye in the plane of the normal and the sun; none from a sun behind the surface.
float phong_specular(vec3 normal, vec3 to_eye) {
    float facing = dot(normal, u_to_sun);
    vec3 mirrored_sun = 2.0 * facing * normal - u_to_sun;
    // Seen in the plane of N and L, M (mirrored_sun) is as far from V as twice H is from N:
    // cos(2x)^(s/4) and cos(x)^s fall alike near the top, both close to exp(-s x^2 / 2).
    return facing > 0.0 ? pow(max(dot(mirrored_sun, to_eye), 0.0), 0.25 * u_shininess) : 0.0;
}
