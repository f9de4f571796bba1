// exercise prepare STEP N WORK_DIR | exercise check STEP N WORK_DIR | exercise list
// The exercises behind ./ocean exercise and ./ocean check (exercises/README.md).
//   prepare: copies the step's shaders into WORK_DIR and empties one function there (its body
//            becomes a TODO that compiles), so the step runs on the learner's copy
//            (--shader-dir, hot reload) with that piece missing.
//   check:   compiles the learner's function on the GPU, evaluates it at many inputs and holds it
//            to the chapter's CPU reference; prints pass, or fail with a hint. Exit 0 on pass.
// The solutions are the chapters' own shaders: an exercise removes a piece of working code.
#include "common/context.hpp"
#include "common/error.hpp"
#include "common/gl.hpp"
#include "common/shader.hpp"
#include "step01_sine2d/sine_sum.hpp"
#include "step02_sine3d/wave_uniforms.hpp"
#include "step03_lighting/lighting.hpp"
#include "step04_fbm/fbm.hpp"
#include "step05_fft/ocean_maps.hpp"
#include "step06_foam_sky/shading.hpp"

#include <glm/vec4.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

namespace {

namespace fs = std::filesystem;
using step03::Vec3;

// What a check found: the worst difference, and where, for the hint.
struct Verdict {
    bool pass = false;
    std::string detail;
};

struct Exercise {
    std::string step;
    int number;
    std::string title;
    std::string file;       // the shader (in the step's shaders/) holding the function
    std::string signature;  // the function's first line, as written there
    std::string stub;       // the body the learner starts from (compiles, does nothing useful)
    std::string task;       // what to write
    std::string hint;       // printed when the check fails
    std::function<Verdict(const fs::path& work)> check;
};

// Runs `expression` (GLSL) once per sample on the GPU, with the learner's `include` (a file of the
// work folder): sample i's inputs are vec4s inputs[stride * i ...], which `declarations` (GLSL
// statements) name. Returns the outputs, or the build error.
std::variant<std::vector<float>, std::string> evaluate_on_gpu(
    const fs::path& work, const std::string& include, const std::string& declarations, const std::string& expression,
    const std::vector<glm::vec4>& packed, int stride, const std::function<void(const ocean::ShaderProgram&)>& set_uniforms) {
    const fs::path shader = work / ".check.comp";
    std::ofstream(shader) << "#version 450 core\nlayout(local_size_x = 64) in;\n#include \"" << include << "\"\n"
                          << "layout(std430, binding = 0) readonly buffer In { vec4 inputs[]; };\n"
                             "layout(std430, binding = 1) writeonly buffer Out { float outputs[]; };\n"
                             "const int STRIDE = " << stride << ";\n"
                             "void main() {\n    int i = int(gl_GlobalInvocationID.x);\n    "
                          << declarations << "\n    outputs[i] = " << expression << ";\n}\n";
    ocean::ShaderProgram program("check", {shader.string()});
    if (auto error = program.build()) return "your shader does not build:\n" + *error;
    const int count = int(packed.size()) / stride;
    ocean::Buffer in = ocean::make_buffer(), out = ocean::make_buffer();
    glNamedBufferStorage(in.id(), GLsizeiptr(packed.size() * sizeof(glm::vec4)), packed.data(), 0);
    glNamedBufferStorage(out.id(), GLsizeiptr(std::size_t(count) * sizeof(float)), nullptr, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    if (set_uniforms) set_uniforms(program);
    glUseProgram(program.id());
    glDispatchCompute(GLuint(count / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> gpu(static_cast<std::size_t>(count));
    glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(gpu.size() * sizeof(float)), gpu.data());
    return gpu;
}

// The learner's values against the reference's: pass when the worst difference is within
// `tolerance` of the largest reference value; the worst case is kept for the message.
Verdict compare(const std::vector<float>& gpu, const std::vector<double>& expected, const std::string& expression,
                double tolerance, const std::string& inputs) {
    double worst = 0, largest = 0, worst_expected = 0, worst_got = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        largest = std::max(largest, std::abs(expected[i]));
        const double difference = std::isfinite(gpu[i]) ? std::abs(gpu[i] - expected[i]) : 1e30;
        if (difference > worst) {
            worst = difference;
            worst_expected = expected[i];
            worst_got = gpu[i];
        }
    }
    std::ostringstream detail;
    detail << expression << ": worst difference " << worst << " (expected " << worst_expected << ", yours "
           << worst_got << ") over " << expected.size() << " " << inputs;
    return {worst <= tolerance * std::max(largest, 1e-12), detail.str()};
}

constexpr int kSamples = 2048;

using Reference = std::function<double(const Vec3& n, const Vec3& v, const Vec3& l, double alpha)>;

// Evaluates `expression` (GLSL, in terms of n, v, l, alpha) with the learner's `include` at 2048
// random normals, eyes and suns, after `set_uniforms`, and compares each value with `reference`.
// With `fixed_sun`, l is that one direction (a chapter whose sun is a uniform); otherwise
// anywhere, below the surface too.
Verdict check_glsl(const fs::path& work, const std::string& include, const std::string& expression,
                   const Reference& reference, double tolerance,
                   const std::function<void(const ocean::ShaderProgram&)>& set_uniforms = {},
                   const Vec3* fixed_sun = nullptr) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> uniform(-1, 1), unit(0, 1);
    auto direction = [&](double min_y) {
        for (;;) {
            const Vec3 d{uniform(random), uniform(random), uniform(random)};
            const double length2 = step03::dot(d, d);
            if (length2 > 1e-3 && length2 <= 1 && d.y / std::sqrt(length2) >= min_y) return step03::normalize(d);
        }
    };
    std::vector<glm::vec4> packed;
    for (int i = 0; i < kSamples; ++i) {
        const Vec3 n = direction(0.5), v = direction(0.02), l = fixed_sun != nullptr ? *fixed_sun : direction(-1.0);
        packed.emplace_back(float(n.x), float(n.y), float(n.z), float(0.02 + 0.6 * unit(random)));
        packed.emplace_back(float(v.x), float(v.y), float(v.z), 0.0f);
        packed.emplace_back(float(l.x), float(l.y), float(l.z), 0.0f);
    }
    const auto result = evaluate_on_gpu(work, include,
                                        "vec3 n = inputs[3 * i].xyz, v = inputs[3 * i + 1].xyz, l = inputs[3 * i + 2].xyz;\n"
                                        "    float alpha = inputs[3 * i].w;",
                                        expression, packed, 3, set_uniforms);
    if (const auto* error = std::get_if<std::string>(&result)) return {false, *error};
    std::vector<double> expected;
    for (int i = 0; i < kSamples; ++i) {
        const glm::vec4 &a = packed[std::size_t(3 * i)], &b = packed[std::size_t(3 * i + 1)], &c = packed[std::size_t(3 * i + 2)];
        expected.push_back(reference({a.x, a.y, a.z}, {b.x, b.y, b.z}, {c.x, c.y, c.z}, a.w));
    }
    return compare(std::get<std::vector<float>>(result), expected, expression, tolerance, "normals, eyes and suns");
}

// Evaluates `expression` (GLSL, in terms of vec4 a and b, each component uniform in [low, high])
// at 2048 random inputs and compares it with `reference(a, b)`: for the wave functions of steps
// 01 to 05.
using ValueReference = std::function<double(const glm::dvec4& a, const glm::dvec4& b)>;
Verdict check_values(const fs::path& work, const std::string& include, const std::string& expression,
                     const ValueReference& reference, double tolerance, double low, double high,
                     const std::function<void(const ocean::ShaderProgram&)>& set_uniforms = {}) {
    std::mt19937 random(13);
    std::uniform_real_distribution<double> uniform(low, high);
    std::vector<glm::vec4> packed;
    for (int i = 0; i < 2 * kSamples; ++i)
        packed.emplace_back(float(uniform(random)), float(uniform(random)), float(uniform(random)), float(uniform(random)));
    const auto result = evaluate_on_gpu(work, include, "vec4 a = inputs[2 * i], b = inputs[2 * i + 1];", expression,
                                        packed, 2, set_uniforms);
    if (const auto* error = std::get_if<std::string>(&result)) return {false, *error};
    std::vector<double> expected;
    for (int i = 0; i < kSamples; ++i)
        expected.push_back(reference(glm::dvec4(packed[std::size_t(2 * i)]), glm::dvec4(packed[std::size_t(2 * i + 1)])));
    return compare(std::get<std::vector<float>>(result), expected, expression, tolerance, "random inputs");
}

// The waves the checks of steps 01 and 02 give the learner's functions, at t = 1.7 s.
constexpr double kCheckTime = 1.7;
const std::vector<step01::Wave> kStep01Waves{{8.0, 0.5, 1.2}, {3.1, 0.2, -0.7}, {1.7, 0.08, 0.9}};
const std::vector<step02::DirectionalWave> kStep02Waves{{20, 14.0, 0.6, 3.0}, {75, 6.5, 0.25, 2.1}, {-40, 3.2, 0.1, 1.4}};

// step01's uniforms as its main.cpp sets them: (w, a, -t phi mod 2 pi, 0) per wave.
void set_step01_waves(const ocean::ShaderProgram& p) {
    std::vector<glm::vec4> packed;
    for (const step01::Wave& w : kStep01Waves)
        packed.emplace_back(float(step01::angular_wavenumber(w)), float(w.amplitude),
                            float(step01::phase_at(step01::phase_rate(w), kCheckTime)), 0.0f);
    p.set("u_wave_count", int(packed.size()));
    p.set("u_waves", packed);
}

// A sample of step05's maps from a and b: displacement (0, 0, 0, l dDx/dz), slopes (dh/dx, dh/dz,
// l dDx/dx, l dDz/dz), as GLSL and as the CPU's OceanMaps (one cell, choppiness 1).
const char* kStep05Sample = "vec4(0.0, 0.0, 0.0, b.x), a";
step05::OceanMaps step05_cell(const glm::dvec4& a, const glm::dvec4& b) {
    step05::OceanMaps maps;
    maps.n = 1;
    for (auto& field : maps.fields) field.assign(1, 0.0);
    maps.fields[step05::SlopeX][0] = a.x;
    maps.fields[step05::SlopeZ][0] = a.y;
    maps.fields[step05::DDxDx][0] = a.z;
    maps.fields[step05::DDzDz][0] = a.w;
    maps.fields[step05::DDxDz][0] = b.x;
    return maps;
}

// Both checks must pass; the first failure is the verdict.
Verdict both(const Verdict& first, const std::function<Verdict()>& second) { return first.pass ? second() : first; }

// step03's light with the sun at `sun`, a white sun, the default water and shininess 64.
step03::Light step03_light(const Vec3& sun) {
    step03::Light light;
    light.to_sun = sun;
    light.sun = {1, 1, 1};
    light.water = {0.05, 0.25, 0.35};
    light.ambient = {0.02, 0.04, 0.06};
    light.shininess = 64;
    return light;
}

// step03's light_terms on the GPU, one term: its uniforms set as step03_light says.
Verdict check_step03_term(const fs::path& work, const std::string& term, double (*pick)(const step03::LightTerms&)) {
    static const Vec3 sun = step03::normalize({0.4, 0.5, -0.3});
    const step03::Light light = step03_light(sun);
    return check_glsl(
        work, "lighting.glsl", "light_terms(n, v)." + term,
        [&](const Vec3& n, const Vec3& v, const Vec3&, double) { return pick(step03::light_terms(n, v, light)); }, 1e-4,
        [&](const ocean::ShaderProgram& p) {
            p.set("u_to_sun", glm::vec3(float(sun.x), float(sun.y), float(sun.z)));
            p.set("u_sun_color", glm::vec3(1.0f));
            p.set("u_water_color", glm::vec3(float(light.water.r), float(light.water.g), float(light.water.b)));
            p.set("u_ambient_color", glm::vec3(float(light.ambient.r), float(light.ambient.g), float(light.ambient.b)));
            p.set("u_shininess", float(light.shininess));
        },
        &sun);
}

std::vector<Exercise> exercises() {
    using step06::Microfacet;
    return {
        {"step01_sine2d", 1, "One sine wave", "sine_sum.glsl", "float wave_height(int i, float x) {",
         "    // TODO (exercise 1): the height of wave i at x.\n    return 0.0;\n",
         "Write wave_height: wave i arrives as u_waves[i] = (w, a, phase, 0), w = 2 pi / wavelength already, and\n"
         "its height at x is a sin(x w + phase). Without it the plot is a flat line.",
         "u_waves[i].x is w (radians per metre), .y the amplitude a, .z the phase (-t phi, reduced on the CPU): "
         "a * sin(x * w + phase). The phase is added, not multiplied.",
         [](const fs::path& work) {
             return check_values(
                 work, "sine_sum.glsl", "sum_of_sines(a.x)",
                 [](const glm::dvec4& a, const glm::dvec4&) { return step01::sum_of_sines(kStep01Waves, a.x, kCheckTime); },
                 1e-4, -20, 20, set_step01_waves);
         }},
        {"step01_sine2d", 2, "The slope of a sine", "sine_sum.glsl", "float wave_slope(int i, float x) {",
         "    // TODO (exercise 2): d/dx of wave i's height at x.\n    return 0.0;\n",
         "Write wave_slope, the derivative of a sin(x w + phase) with respect to x. The plot uses it to draw\n"
         "its line equally thick on steep slopes: without it the line thins where the wave is steep.",
         "The chain rule brings w out of the sine, and the amplitude stays: a w cos(x w + phase). The notes' 2.2 "
         "writes cos(...) alone, without w a: that is the slope of a wave of one radian per metre and amplitude 1.",
         [](const fs::path& work) {
             return check_values(
                 work, "sine_sum.glsl", "sum_of_sines_slope(a.x)",
                 [](const glm::dvec4& a, const glm::dvec4&) {
                     return step01::sum_of_sines_slope(kStep01Waves, a.x, kCheckTime);
                 },
                 1e-4, -20, 20, set_step01_waves);
         }},
        {"step02_sine3d", 1, "Waves with a direction", "waves.glsl", "float wave_height(vec2 xz) {",
         "    // TODO (exercise 1): the sum of the directional waves at xz.\n    return 0.0;\n",
         "Write wave_height: the sum over the u_wave_count waves of a sin(dot(d, xz) w + phase), with\n"
         "u_waves[i] = (d.x, d.z, w, a) and the phase in u_wave_phases[i]. Without it the sea is flat.",
         "dot(d, xz) is how far along the wave's direction the point lies: crests are lines across d. "
         "u_waves[i].xy is d, .z is w, .w is a; the phase is its own uniform array, u_wave_phases[i].",
         [](const fs::path& work) {
             return check_values(
                 work, "waves.glsl", "wave_height(a.xy)",
                 [](const glm::dvec4& a, const glm::dvec4&) { return step02::height(kStep02Waves, a.x, a.y, kCheckTime); },
                 1e-4, -60, 60,
                 [](const ocean::ShaderProgram& p) { step02::upload_waves(p, kStep02Waves, kCheckTime); });
         }},
        {"step04_fbm", 1, "The exp-sine wave and its derivatives", "fbm.glsl", "vec3 wave_shape(float theta) {",
         "    // TODO (exercise 1): (W, W', W'') of the exp-sine wave, mean removed. For now, a sine.\n"
         "    return vec3(sin(theta), cos(theta), -sin(theta));\n",
         "Write wave_shape for SHAPE 1: W = e^(sin theta - 1) - 0.46575961 (its mean, so the sea stays at y = 0),\n"
         "W' = dW/dtheta and W'' = d2W/dtheta2. W' makes the normals, W'' the domain warp's Jacobian.\n"
         "The starter is step02's sine: round crests, as wide as the troughs.",
         "d/dtheta e^(sin theta - 1) = e^(sin theta - 1) cos theta; differentiate that product again: "
         "e^(sin theta - 1)(cos^2 theta - sin theta). The mean is subtracted from W only.",
         [](const fs::path& work) {
             using step04::Shape;
             const auto component = [&](const char* swizzle, double step04::ShapeValue::*part) {
                 return check_values(
                     work, "fbm.glsl", std::string("wave_shape(a.x).") + swizzle,
                     [part](const glm::dvec4& a, const glm::dvec4&) { return step04::wave_shape(Shape::ExpSine, a.x).*part; },
                     1e-4, -10, 10);
             };
             return both(component("x", &step04::ShapeValue::value), [&] {
                 return both(component("y", &step04::ShapeValue::first),
                             [&] { return component("z", &step04::ShapeValue::second); });
             });
         }},
        {"step04_fbm", 2, "The normal from the gradient", "fbm.glsl", "vec3 fbm_normal(vec2 gradient) {",
         "    // TODO (exercise 2): the unit normal from (dh/dx, dh/dz).\n    return vec3(0.0, 1.0, 0.0);\n",
         "Write fbm_normal: with the tangents T = (1, dh/dx, 0) and B = (0, dh/dz, 1), N = B x T, normalised.\n"
         "The starter's normal is straight up: the sea is lit as if flat.",
         "B x T = (-dh/dx, 1, -dh/dz) before normalising; T x B points down, into the water (then the light is "
         "on the wrong side of every wave).",
         [](const fs::path& work) {
             const auto component = [&](const char* swizzle, double step03::Vec3::*part) {
                 return check_values(
                     work, "fbm.glsl", std::string("fbm_normal(a.xy).") + swizzle,
                     [part](const glm::dvec4& a, const glm::dvec4&) { return step03::normal({0.0, a.x, a.y}).*part; },
                     1e-4, -2, 2);
             };
             return both(component("x", &step03::Vec3::x), [&] {
                 return both(component("y", &step03::Vec3::y), [&] { return component("z", &step03::Vec3::z); });
             });
         }},
        {"step05_fft", 1, "Where the surface folds", "ocean_maps.glsl", "float jacobian(vec4 displacement, vec4 slopes) {",
         "    // TODO (exercise 1): the Jacobian of the choppy displacement.\n    return 1.0;\n",
         "Write jacobian: J = (1 + l dDx/dx)(1 + l dDz/dz) - (l dDx/dz)^2, with l dDx/dx = slopes.z, l dDz/dz =\n"
         "slopes.w, l dDx/dz = displacement.w. J < 0 where the surface folds over itself: view=jacobian shows\n"
         "it, and step06 puts its foam there.",
         "J is the determinant of the 2 x 2 matrix [[1 + l dDx/dx, l dDx/dz], [l dDx/dz, 1 + l dDz/dz]]: the "
         "product of the diagonal minus the square of the off-diagonal term (the maps hold l D already).",
         [](const fs::path& work) {
             return check_values(
                 work, "ocean_maps.glsl", std::string("jacobian(") + kStep05Sample + ")",
                 [](const glm::dvec4& a, const glm::dvec4& b) { return step05_cell(a, b).jacobian(0, 1.0); }, 1e-4, -0.8,
                 0.8);
         }},
        {"step05_fft", 2, "The normal of the choppy surface", "ocean_maps.glsl",
         "vec3 choppy_normal(vec4 displacement, vec4 slopes) {",
         "    // TODO (exercise 2): the normal of the displaced surface. For now, step03's.\n"
         "    return normalize(vec3(-slopes.x, 1.0, -slopes.y));\n",
         "Write choppy_normal: the surface point of rest position p is P = (p.x + l Dx, h, p.z + l Dz); its\n"
         "tangents are dP/dx = (1 + l dDx/dx, dh/dx, l dDx/dz) and dP/dz = (l dDx/dz, dh/dz, 1 + l dDz/dz), and\n"
         "N = normalize(dP/dz x dP/dx). The starter is step03's normal, right only where l = 0.",
         "slopes = (dh/dx, dh/dz, l dDx/dx, l dDz/dz), displacement.w = l dDx/dz (= l dDz/dx). The order of the "
         "cross product decides up or down: dP/dz x dP/dx points up for a flat sea.",
         [](const fs::path& work) {
             const auto component = [&](const char* swizzle, int index) {
                 return check_values(
                     work, "ocean_maps.glsl", std::string("choppy_normal(") + kStep05Sample + ")." + swizzle,
                     [index](const glm::dvec4& a, const glm::dvec4& b) {
                         return step05_cell(a, b).normal(0, 1.0)[std::size_t(index)];
                     },
                     1e-4, -0.6, 0.6);
             };
             return both(component("x", 0), [&] { return both(component("y", 1), [&] { return component("z", 2); }); });
         }},
        {"step03_lighting", 1, "Lambert and Blinn-Phong", "lighting.glsl", "LightTerms light_terms(vec3 normal, vec3 to_eye) {",
         "    // TODO (exercise 1): ambient, Lambert diffuse and Blinn-Phong specular.\n"
         "    LightTerms t;\n    t.ambient = u_ambient_color;\n    t.diffuse = vec3(0.0);\n    t.specular = vec3(0.0);\n"
         "    return t;\n",
         "Write light_terms: diffuse = water * sun * max(N.L, 0) (Lambert); specular = sun * max(N.H, 0)^shininess "
         "with the halfway vector H = normalize(V + L), and no specular when the sun is behind the surface "
         "(N.L <= 0). Without them the sea is flat ambient colour.",
         "H is normalize(to_eye + to_sun), the direction halfway between eye and sun, not the reflection of either; "
         "the specular needs N.L > 0 (a sun below the surface makes no glint) even where N.H is large.",
         [](const fs::path& work) {
             const Verdict diffuse = check_step03_term(work, "diffuse.y", [](const step03::LightTerms& t) { return t.diffuse.g; });
             if (!diffuse.pass) return diffuse;
             return check_step03_term(work, "specular.x", [](const step03::LightTerms& t) { return t.specular.r; });
         }},
        {"step06_foam_sky", 1, "Schlick's Fresnel", "shading.glsl", "float fresnel_schlick(float cos_theta, float f0) {",
         "    // TODO (exercise 1): how much light the water reflects, seen at cos_theta from the normal.\n"
         "    return 0.0;\n",
         "Write fresnel_schlick: F = F0 + (1 - F0)(1 - cos theta)^5, with cos theta clamped to [0, 1].\n"
         "Without it the sea reflects nothing: no sky in the water, no glint.",
         "Looking straight down (cos theta = 1) water reflects F0 = 0.02; at grazing (cos theta = 0), "
         "everything (1). Check both ends of your formula, and clamp cos theta: a normal bent past 90 degrees "
         "gives a negative one.",
         [](const fs::path& work) {
             return check_glsl(work, "shading.glsl", "fresnel_schlick(dot(n, v), 0.02)",
                                  [](const Vec3& n, const Vec3& v, const Vec3&, double) {
                                      return step06::fresnel_schlick(step03::dot(n, v), 0.02);
                                  },
                                  1e-4);
         }},
        {"step06_foam_sky", 2, "The microfacet specular", "shading.glsl",
         "vec3 specular_term(vec3 n, vec3 v, vec3 l, float alpha, float f0, vec3 sun) {",
         "    // TODO (exercise 2): the sun's reflection towards v: sun * D * G * F / (4 N.V).\n"
         "    return vec3(0.0);\n",
         "Write specular_term from the parts above it: H = normalize(V + L), D = "
         "microfacet_distribution(N.H, alpha), G = 1 / (1 + smith_lambda(N.V) + smith_lambda(N.L)), F = "
         "fresnel_schlick(V.H, f0); return sun D G F / (4 N.V), and nothing when the sun or the eye is below "
         "the surface (N.L <= 0 or N.V <= 0). Without it there is no sun glint.",
         "Fresnel takes V.H here, not N.V (the microfacets that reflect the sun face H); the 4 N.V in the "
         "denominator is N.V alone (N.L cancels with the irradiance); return vec3(0.0) for N.L <= 0 or N.V <= 0.",
         [](const fs::path& work) {
             return check_glsl(work, "shading.glsl", "specular_term(n, v, l, alpha, 0.02, vec3(1.0)).x",
                                  [](const Vec3& n, const Vec3& v, const Vec3& l, double alpha) {
                                      return step06::specular_factor(n, v, l, alpha, 0.02, Microfacet::Ggx);
                                  },
                                  1e-4);
         }},
    };
}

const Exercise* find(const std::string& step, int number) {
    static const std::vector<Exercise> all = exercises();
    for (const Exercise& e : all)
        if (e.step == step && e.number == number) return &e;
    return nullptr;
}

// The step's shaders copied into `work`, with the exercise's function body replaced by its stub.
void prepare(const Exercise& e, const fs::path& work) {
    const fs::path source = fs::path(OCEAN_SOURCE_DIR) / e.step / "shaders";
    fs::create_directories(work);
    for (const auto& entry : fs::directory_iterator(source))
        if (entry.is_regular_file()) fs::copy_file(entry.path(), work / entry.path().filename(), fs::copy_options::overwrite_existing);
    std::ifstream in(work / e.file);
    std::ostringstream out;
    bool inside = false, found = false;
    for (std::string line; std::getline(in, line);) {
        if (!inside && line == e.signature) {
            out << line << '\n' << e.stub << "}\n";
            inside = found = true;
            continue;
        }
        if (inside) {
            if (line == "}") inside = false;  // the function's closing brace, at column 0
            continue;
        }
        out << line << '\n';
    }
    if (!found) throw ocean::Error("exercise: '" + e.signature + "' not found in " + (work / e.file).string());
    std::ofstream(work / e.file) << out.str();
}

int usage() {
    std::fprintf(stderr, "usage: exercise list | exercise prepare|check STEP N WORK_DIR\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const std::string verb = argc > 1 ? argv[1] : "";
        if (verb == "list" && argc == 2) {
            for (const Exercise& e : exercises()) std::printf("%s %d  %s (%s)\n", e.step.c_str(), e.number, e.title.c_str(), e.file.c_str());
            return 0;
        }
        if ((verb != "prepare" && verb != "check") || argc != 5) return usage();
        const Exercise* e = find(argv[2], std::atoi(argv[3]));
        if (e == nullptr) {
            std::fprintf(stderr, "exercise: no exercise %s of %s (exercise list names them)\n", argv[3], argv[2]);
            return 2;
        }
        const fs::path work = argv[4];
        if (verb == "prepare") {
            prepare(*e, work);
            std::printf("exercise %d of %s: %s\n%s\nedit %s (the step reloads it when you save)\n", e->number,
                        e->step.c_str(), e->title.c_str(), e->task.c_str(), (work / e->file).string().c_str());
            return 0;
        }
        if (!fs::exists(work / e->file)) {
            std::fprintf(stderr, "exercise: %s does not exist: start with ./ocean exercise %s %d\n",
                         (work / e->file).string().c_str(), e->step.c_str(), e->number);
            return 2;
        }
        const auto context = ocean::Context::create({true, 16, 16, "exercise check"});
        const Verdict verdict = e->check(work);
        std::printf("%s: exercise %d of %s (%s): %s\n", verdict.pass ? "pass" : "fail", e->number, e->step.c_str(),
                    e->title.c_str(), verdict.detail.c_str());
        if (!verdict.pass) std::printf("hint: %s\n", e->hint.c_str());
        return verdict.pass ? 0 : 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "exercise: %s\n", error.what());
        return 1;
    }
}
