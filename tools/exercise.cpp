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
#include "step03_lighting/lighting.hpp"
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

using Reference = std::function<double(const Vec3& n, const Vec3& v, const Vec3& l, double alpha)>;

// Evaluates `expression` (GLSL, in terms of n, v, l, alpha) with the learner's `include` (a file of
// the work folder) at 2048 random normals, eyes and suns, after `set_uniforms`, and compares each
// value with `reference`. With `fixed_sun`, l is that one direction (a chapter whose sun is a
// uniform); otherwise anywhere, below the surface too.
Verdict check_glsl(const fs::path& work, const std::string& include, const std::string& expression,
                   const Reference& reference, double tolerance,
                   const std::function<void(const ocean::ShaderProgram&)>& set_uniforms = {},
                   const Vec3* fixed_sun = nullptr) {
    const fs::path shader = work / ".check.comp";
    std::ofstream(shader) << "#version 450 core\nlayout(local_size_x = 64) in;\n#include \"" << include << "\"\n"
                          << "layout(std430, binding = 0) readonly buffer In { vec4 inputs[]; };\n"
                             "layout(std430, binding = 1) writeonly buffer Out { float outputs[]; };\n"
                             "void main() {\n    int i = int(gl_GlobalInvocationID.x);\n"
                             "    vec3 n = inputs[3 * i].xyz, v = inputs[3 * i + 1].xyz, l = inputs[3 * i + 2].xyz;\n"
                             "    float alpha = inputs[3 * i].w;\n    outputs[i] = "
                          << expression << ";\n}\n";
    ocean::ShaderProgram program("check", {shader.string()});
    if (auto error = program.build()) return {false, "your shader does not build:\n" + *error};
    constexpr int kCount = 2048;
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
    for (int i = 0; i < kCount; ++i) {
        const Vec3 n = direction(0.5), v = direction(0.02), l = fixed_sun != nullptr ? *fixed_sun : direction(-1.0);
        packed.emplace_back(float(n.x), float(n.y), float(n.z), float(0.02 + 0.6 * unit(random)));
        packed.emplace_back(float(v.x), float(v.y), float(v.z), 0.0f);
        packed.emplace_back(float(l.x), float(l.y), float(l.z), 0.0f);
    }
    ocean::Buffer in = ocean::make_buffer(), out = ocean::make_buffer();
    glNamedBufferStorage(in.id(), GLsizeiptr(packed.size() * sizeof(glm::vec4)), packed.data(), 0);
    glNamedBufferStorage(out.id(), GLsizeiptr(kCount * sizeof(float)), nullptr, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    if (set_uniforms) set_uniforms(program);
    glUseProgram(program.id());
    glDispatchCompute(kCount / 64, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> gpu(kCount);
    glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(gpu.size() * sizeof(float)), gpu.data());
    double worst = 0, largest = 0, worst_expected = 0, worst_got = 0;
    for (int i = 0; i < kCount; ++i) {
        const glm::vec4 &a = packed[std::size_t(3 * i)], &b = packed[std::size_t(3 * i + 1)], &c = packed[std::size_t(3 * i + 2)];
        const double expected = reference({a.x, a.y, a.z}, {b.x, b.y, b.z}, {c.x, c.y, c.z}, a.w);
        largest = std::max(largest, std::abs(expected));
        const double difference = std::isfinite(gpu[std::size_t(i)]) ? std::abs(gpu[std::size_t(i)] - expected) : 1e30;
        if (difference > worst) {
            worst = difference;
            worst_expected = expected;
            worst_got = gpu[std::size_t(i)];
        }
    }
    std::ostringstream detail;
    detail << expression << ": worst difference " << worst << " (expected " << worst_expected << ", yours "
           << worst_got << ") over " << kCount << " normals, eyes and suns";
    return {worst <= tolerance * std::max(largest, 1e-12), detail.str()};
}

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
