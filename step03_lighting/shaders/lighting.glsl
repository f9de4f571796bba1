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
