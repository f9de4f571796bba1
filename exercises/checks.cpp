// How a GLSL exercise is checked: the learner's function compiled into a compute shader with the
// work folder's copy of the chapter's file, run at 2048 inputs, and held to the chapter's CPU
// reference in double. (The tool runs the whole check in a child process under a time limit: a
// learner's endless loop stops there, exercises/main.cpp.)
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <random>
#include <sstream>
#include <variant>

#include "common/error.hpp"
#include "common/file_output.hpp"
#include "common/gl.hpp"
#include "exercises/exercise.hpp"

namespace exercises {

namespace {

constexpr int kSamples = 2048;

// Runs `expression` (GLSL) once per sample on the GPU, with the learner's `include` (a file of the
// work folder): sample i's inputs are vec4s inputs[stride * i ...], which `declarations` (GLSL
// statements) name. Returns the outputs, or the build error.
std::variant<std::vector<float>, std::string> evaluate_on_gpu(const fs::path& work,
                                                              const std::string& include,
                                                              const std::string& declarations,
                                                              const std::string& expression,
                                                              const std::vector<glm::vec4>& packed,
                                                              int stride, const SetUniforms& set_uniforms) {
    const fs::path shader = work / ".check.comp";
    std::ostringstream source;
    source << "#version 450 core\nlayout(local_size_x = 64) in;\n";
    std::istringstream names(include);  // `include` may name several files, separated by commas
    for (std::string name; std::getline(names, name, ',');) source << "#include \"" << name << "\"\n";
    source << "layout(std430, binding = 0) readonly buffer In { vec4 inputs[]; };\n"
              "layout(std430, binding = 1) writeonly buffer Out { float outputs[]; };\n"
              "const int STRIDE = "
           << stride
           << ";\n"
              "void main() {\n    int i = int(gl_GlobalInvocationID.x);\n    "
           << declarations << "\n    outputs[i] = " << expression << ";\n}\n";
    if (auto error = ocean::write_file(shader, source.str())) throw ocean::Error(*error);
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
Verdict compare(const std::vector<float>& gpu, const std::vector<double>& expected,
                const std::string& expression, double tolerance, const std::string& inputs) {
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

}  // namespace

Verdict check_glsl(const fs::path& work, const std::string& include, const std::string& expression,
                   const Reference& reference, double tolerance, const SetUniforms& set_uniforms,
                   const glm::dvec3* fixed_sun) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> uniform(-1, 1), unit(0, 1);
    auto direction = [&](double min_y) {
        for (;;) {
            const glm::dvec3 d{uniform(random), uniform(random), uniform(random)};
            const double length2 = glm::dot(d, d);
            if (length2 > 1e-3 && length2 <= 1 && d.y / std::sqrt(length2) >= min_y)
                return d / std::sqrt(length2);
        }
    };
    std::vector<glm::vec4> packed;
    for (int i = 0; i < kSamples; ++i) {
        const glm::dvec3 n = direction(0.5), v = direction(0.02),
                         l = fixed_sun != nullptr ? *fixed_sun : direction(-1.0);
        packed.emplace_back(glm::vec3(n), float(0.02 + 0.6 * unit(random)));
        packed.emplace_back(glm::vec3(v), 0.0f);
        packed.emplace_back(glm::vec3(l), 0.0f);
    }
    const auto result =
        evaluate_on_gpu(work, include,
                        "vec3 n = inputs[3 * i].xyz, v = inputs[3 * i + 1].xyz, l = inputs[3 * i + 2].xyz;\n"
                        "    float alpha = inputs[3 * i].w;",
                        expression, packed, 3, set_uniforms);
    if (const auto* error = std::get_if<std::string>(&result)) return {false, *error};
    std::vector<double> expected;
    for (int i = 0; i < kSamples; ++i) {
        const glm::vec4 &a = packed[std::size_t(3 * i)], &b = packed[std::size_t(3 * i + 1)],
                        &c = packed[std::size_t(3 * i + 2)];
        expected.push_back(reference(glm::dvec3(a), glm::dvec3(b), glm::dvec3(c), a.w));
    }
    return compare(std::get<std::vector<float>>(result), expected, expression, tolerance,
                   "normals, eyes and suns");
}

Verdict check_values(const fs::path& work, const std::string& include, const std::string& expression,
                     const ValueReference& reference, double tolerance, double low, double high,
                     const SetUniforms& set_uniforms) {
    std::mt19937 random(13);
    std::uniform_real_distribution<double> uniform(low, high);
    std::vector<glm::vec4> packed;
    for (int i = 0; i < 2 * kSamples; ++i)
        packed.emplace_back(float(uniform(random)), float(uniform(random)), float(uniform(random)),
                            float(uniform(random)));
    const auto result = evaluate_on_gpu(work, include, "vec4 a = inputs[2 * i], b = inputs[2 * i + 1];",
                                        expression, packed, 2, set_uniforms);
    if (const auto* error = std::get_if<std::string>(&result)) return {false, *error};
    std::vector<double> expected;
    for (int i = 0; i < kSamples; ++i)
        expected.push_back(
            reference(glm::dvec4(packed[std::size_t(2 * i)]), glm::dvec4(packed[std::size_t(2 * i + 1)])));
    return compare(std::get<std::vector<float>>(result), expected, expression, tolerance, "random inputs");
}

Verdict check_vector(const fs::path& work, const std::string& include, const std::string& expression,
                     const VectorReference& reference, double tolerance, double low, double high,
                     const SetUniforms& set_uniforms, int components) {
    Verdict verdict;
    for (int c = 0; c < components; ++c) {
        verdict = check_values(
            work, include, expression + "." + "xyz"[c],
            [&](const glm::dvec4& a, const glm::dvec4& b) { return reference(a, b)[c]; }, tolerance, low,
            high, set_uniforms);
        if (!verdict.pass) break;
    }
    return verdict;
}

}  // namespace exercises
