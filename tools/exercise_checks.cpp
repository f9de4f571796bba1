// How an exercise is checked: the learner's GLSL function compiled into a compute shader with the
// work folder's copy of the chapter's file, run at 2048 inputs, and held to the chapter's CPU
// reference in double.
#include "tools/exercise.hpp"

#include "common/gl.hpp"
#include "common/program_library.hpp"
#include "step05_fft/ocean_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <variant>

namespace exercises {

namespace {

constexpr int kSamples = 2048;

// Runs `expression` (GLSL) once per sample on the GPU, with the learner's `include` (a file of the
// work folder): sample i's inputs are vec4s inputs[stride * i ...], which `declarations` (GLSL
// statements) name. Returns the outputs, or the build error.
std::variant<std::vector<float>, std::string> evaluate_on_gpu(
    const fs::path& work, const std::string& include, const std::string& declarations, const std::string& expression,
    const std::vector<glm::vec4>& packed, int stride, const std::function<void(const ocean::ShaderProgram&)>& set_uniforms) {
    const fs::path shader = work / ".check.comp";
    std::ostringstream includes;  // `include` may name several files, separated by commas
    std::istringstream names(include);
    for (std::string name; std::getline(names, name, ',');) includes << "#include \"" << name << "\"\n";
    std::ofstream(shader) << "#version 450 core\nlayout(local_size_x = 64) in;\n" << includes.str()
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


}  // namespace

Verdict check_glsl(const fs::path& work, const std::string& include, const std::string& expression,
                   const Reference& reference, double tolerance,
                   const SetUniforms& set_uniforms, const Vec3* fixed_sun) {
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

Verdict check_values(const fs::path& work, const std::string& include, const std::string& expression,
                     const ValueReference& reference, double tolerance, double low, double high,
                     const SetUniforms& set_uniforms) {
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

Verdict check_vector(const fs::path& work, const std::string& include, const std::string& expression,
                     const VectorReference& reference, double tolerance, double low, double high,
                     const SetUniforms& set_uniforms, int components) {
    Verdict verdict;
    for (int c = 0; c < components; ++c) {
        verdict = check_values(
            work, include, expression + "." + "xyz"[c],
            [&](const glm::dvec4& a, const glm::dvec4& b) { return reference(a, b)[c]; }, tolerance, low, high,
            set_uniforms);
        if (!verdict.pass) break;
    }
    return verdict;
}

Verdict check_fft(const fs::path& work, step05::GpuFftForm form) {
    // The chapter's programs as the step gets them, its own shaders read from the work folder.
    ocean::ProgramLibrary programs;
    programs.set_shader_dir(std::string(OCEAN_SOURCE_DIR) + "/step05_fft/shaders", work.string());
    const ocean::ProgramFactory factory = programs.factory();
    std::ostringstream detail;
    for (int n : {64, 128, 256, 512}) {
        step05::SpectrumParams p;
        p.resolution = n;
        const step05::InitialSpectrum sizes = step05::initial_spectrum(p);  // only to size the buffers
        step05::OceanSimulation ocean(factory);
        ocean.set_spectra({&sizes});
        ocean.set_gpu_fft_form(form);
        std::mt19937 random{unsigned(n)};
        std::uniform_real_distribution<float> uniform(-1, 1);
        std::vector<float> input(std::size_t(n) * n * 2);  // the first of the four fields
        for (float& v : input) v = uniform(random);
        glNamedBufferSubData(ocean.spectra_buffer(), 0, GLsizeiptr(input.size() * sizeof(float)), input.data());
        try {
            ocean.transform_fft(ocean.spectra_buffer(), ocean.fields_buffer(), 1);
        } catch (const std::exception& error) {
            return {false, std::string("your shader does not build: ") + error.what()};
        }
        const std::vector<float> output = ocean.read_fields();
        step05::ComplexField field(std::size_t(n) * n);
        for (std::size_t i = 0; i < field.size(); ++i) field[i] = {input[2 * i], input[2 * i + 1]};
        const step05::ComplexField reference = step05::inverse_fft_2d(field, n);
        double worst = 0, largest = 0;
        std::size_t worst_at = 0;
        for (std::size_t i = 0; i < reference.size(); ++i) {
            const std::complex<double> gpu(output[2 * i], output[2 * i + 1]);
            const double difference = std::isfinite(gpu.real() + gpu.imag()) ? std::abs(gpu - reference[i]) : 1e30;
            largest = std::max(largest, std::abs(reference[i]));
            if (difference > worst) worst = difference, worst_at = i;
        }
        detail << "N = " << n << ": worst |yours - reference| " << worst << " of " << largest << " (at x = "
               << worst_at % std::size_t(n) << ", z = " << worst_at / std::size_t(n) << ")";
        if (worst > 1e-4 * largest) return {false, detail.str()};
        detail << "; ";
    }
    return {true, detail.str() + "the inverse 2D transform of random spectra"};
}

bool is_cpp(const std::string& file) { return fs::path(file).extension() == ".cpp"; }

Verdict check_cpp(const fs::path& work, const std::string& file, const std::string& driver, int cases,
                  const CaseReference& reference, double tolerance) {
    std::ofstream(work / "check_driver.cpp") << driver;
    const fs::path exe = work / "check_driver", log = work / "check_compile.log", output = work / "check_output.txt";
    const std::string compile = std::string("'") + OCEAN_CXX_COMPILER + "' -std=c++17 -O1 -I'" + OCEAN_SOURCE_DIR +
                                "' '" + (work / "check_driver.cpp").string() + "' '" + (work / file).string() + "' -o '" +
                                exe.string() + "' > '" + log.string() + "' 2>&1";
    if (std::system(compile.c_str()) != 0) {
        std::ifstream in(log);
        std::string line, first_error;
        while (std::getline(in, line))
            if (line.find("error") != std::string::npos) {
                first_error = line;
                break;
            }
        return {false, file + " does not compile: " + first_error + " (all of it: " + log.string() + ")"};
    }
    const std::string run = "'" + exe.string() + "' " + std::to_string(cases) + " > '" + output.string() + "'";
    if (std::system(run.c_str()) != 0) return {false, "the check's program stopped before it finished (a crash in " + file + "?)"};
    std::ifstream in(output);
    double scale = 0;
    std::vector<std::vector<double>> expected;
    for (int c = 0; c < cases; ++c) {
        expected.push_back(reference(c));
        for (double v : expected.back()) scale = std::max(scale, std::abs(v));
    }
    double worst = -1;
    int worst_case = 0;
    std::size_t worst_value = 0;
    std::vector<double> worst_got;
    for (int c = 0; c < cases; ++c) {
        std::string line;
        if (!std::getline(in, line)) return {false, "the check's program printed " + std::to_string(c) + " of " + std::to_string(cases) + " cases"};
        std::istringstream values(line);
        std::vector<double> got;
        for (double v; values >> v;) got.push_back(v);
        if (got.size() != expected[std::size_t(c)].size()) return {false, "case " + std::to_string(c) + ": wrong count of values"};
        for (std::size_t i = 0; i < got.size(); ++i) {
            const double error = std::isfinite(got[i]) ? std::abs(got[i] - expected[std::size_t(c)][i]) : INFINITY;
            if (error > worst) worst = error, worst_case = c, worst_value = i, worst_got = got;
        }
    }
    std::ostringstream detail;
    detail << "worst difference " << worst << " (" << worst / std::max(scale, 1e-30) << " of the largest value) at case "
           << worst_case << ", value " << worst_value << ": got " << worst_got[worst_value] << ", expected "
           << expected[std::size_t(worst_case)][worst_value] << "; tolerance " << tolerance << " of the largest, over "
           << cases << " cases";
    return {worst <= tolerance * scale, detail.str()};
}

}  // namespace exercises
