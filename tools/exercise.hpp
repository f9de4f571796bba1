// The exercises' pieces shared by tools/exercise.cpp (prepare, check, list), exercise_checks.cpp
// (how a learner's GLSL is evaluated on the GPU and held to a CPU reference) and each chapter's
// STEP/exercises.cpp (the exercises themselves).
#pragma once

#include "common/shader.hpp"
#include "step03_lighting/normals.hpp"
#include "step05_fft/ocean_simulation.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace exercises {

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
    std::string task;       // the principle and what to derive (no formula: the learner tries first)
    std::string hint;       // a nudge, printed when the check fails
    std::string formula;    // the answer's formula, printed only on request (./ocean exercise STEP N --hint)
    // The step's flags that make it run the code this exercise edits, so the starter shows
    // (step05's GPU exercises need backend=gpu_fft: on a CPU-only machine auto picks FFTW).
    std::vector<std::string> run_flags;
    std::function<Verdict(const fs::path& work)> check;
};

// Every exercise, in step and number order (`exercise list`): the chapters' own, each
// STEP/exercises.cpp registering its list with a Registration at start-up.
std::vector<Exercise> all();
struct Registration {
    explicit Registration(std::vector<Exercise> (*chapter)());
};

using Reference = std::function<double(const Vec3& n, const Vec3& v, const Vec3& l, double alpha)>;
using ValueReference = std::function<double(const glm::dvec4& a, const glm::dvec4& b)>;
using SetUniforms = std::function<void(const ocean::ShaderProgram&)>;

// Evaluates `expression` (GLSL, in terms of n, v, l, alpha) with the learner's `include` (a file of
// the work folder) at 2048 random normals, eyes and suns, after `set_uniforms`, and compares each
// value with `reference` within `tolerance` of the largest. With `fixed_sun`, l is that one
// direction (a chapter whose sun is a uniform); otherwise anywhere, below the surface too.
Verdict check_glsl(const fs::path& work, const std::string& include, const std::string& expression,
                   const Reference& reference, double tolerance, const SetUniforms& set_uniforms = {},
                   const Vec3* fixed_sun = nullptr);

// Evaluates `expression` (GLSL, in terms of vec4 a and b, each component uniform in [low, high])
// at 2048 random inputs and compares it with `reference(a, b)`: for the wave functions of steps
// 01 to 05.
Verdict check_values(const fs::path& work, const std::string& include, const std::string& expression,
                     const ValueReference& reference, double tolerance, double low, double high,
                     const SetUniforms& set_uniforms = {});

// A vec3 (or, with components = 2, a vec2) `expression` held to `reference`, component by
// component as check_values does (x, then y, then z): the first component that fails is the verdict.
using VectorReference = std::function<glm::dvec3(const glm::dvec4& a, const glm::dvec4& b)>;
Verdict check_vector(const fs::path& work, const std::string& include, const std::string& expression,
                     const VectorReference& reference, double tolerance, double low, double high,
                     const SetUniforms& set_uniforms = {}, int components = 3);

// A C++ exercise: its file is a .cpp of the step's folder, not a shader (is_cpp), and it is checked
// on the CPU. `driver` (C++ source, written beside the learner's file) is compiled with it by the
// compiler that built this tool, with the repository on the include path, and run with the number
// of cases as its argument: it prints one line of numbers a case. Each line is held to
// reference(case) within `tolerance` of the largest reference value.
bool is_cpp(const std::string& file);
using CaseReference = std::function<std::vector<double>(int index)>;
Verdict check_cpp(const fs::path& work, const std::string& file, const std::string& driver, int cases,
                  const CaseReference& reference, double tolerance);

// step05's inverse FFT in `form` with the work folder's shader (fft_radix2.comp or fft.comp), run by
// the chapter's own OceanSimulation (its buffers, twiddle table and dispatches) on random spectra at
// N = 64, 128, 256 and 512 (for Stockham4: radix-4 stages, and a radix-2 stage last where log2 N is
// odd), against the CPU reference transform.
Verdict check_fft(const fs::path& work, step05::GpuFftForm form);

}  // namespace exercises
