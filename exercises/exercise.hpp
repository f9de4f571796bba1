// The exercise framework (exercises/README.md): what an exercise is, how a chapter registers its
// list (STEP/exercises.cpp), and the checks that hold a learner's function to the chapter's CPU
// reference: GLSL on the GPU (check_glsl, check_values, check_vector), C++ compiled with a small
// program (check_cpp). It knows no chapter: each chapter includes it and passes its own
// references in, so the framework sits below the chapters, on common/ and glm alone.
#pragma once

#include <filesystem>
#include <functional>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "common/shader.hpp"

namespace exercises {

namespace fs = std::filesystem;

// What a check found: the worst difference, and where. `formula_hint` is false when the failure is
// not about the formula (a program stopped at its time limit, a crash, output that is not numbers):
// the exercise's hint would only distract then.
struct Verdict {
    bool pass = false;
    std::string detail;
    bool formula_hint = true;
};

struct Exercise {
    std::string step;
    int number;
    std::string title;
    std::string file;       // the shader (in the step's shaders/) or C++ file (in the step's folder)
    std::string signature;  // the function's first line, as written there
    std::string stub;       // the body the learner starts from (compiles, does nothing useful)
    std::string task;       // the principle and what to derive (no formula: the learner tries first)
    std::string hint;       // a nudge, printed when the check fails
    std::string formula;    // the answer's formula, printed only on request (./ocean exercise STEP N --hint)
    // The step's flags that make it run the code this exercise edits, so the starter shows
    // (step05's GPU exercises need backend=gpu_fft: on a CPU-only machine auto picks FFTW).
    std::vector<std::string> run_flags;
    std::function<Verdict(const fs::path& work)> check;
    // A variant the learner derives with the lesson's method (kDerived): no page gives its answer,
    // and the copies the chapter's other exercises hand out keep its function empty too.
    bool derived = false;
};
constexpr bool kDerived = true;

// Every exercise, in step and number order (`exercise list`): the chapters' own, each
// STEP/exercises.cpp registering its list with a Registration at start-up.
std::vector<Exercise> all();
struct Registration {
    explicit Registration(std::vector<Exercise> (*chapter)());
};

// A C++ exercise: its file is a .cpp of the step's folder, not a shader; it is checked on the CPU
// and needs no GL context.
bool is_cpp(const std::string& file);

using Reference =
    std::function<double(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double alpha)>;
using ValueReference = std::function<double(const glm::dvec4& a, const glm::dvec4& b)>;
using VectorReference = std::function<glm::dvec3(const glm::dvec4& a, const glm::dvec4& b)>;
using SetUniforms = std::function<void(const ocean::ShaderProgram&)>;

// Evaluates `expression` (GLSL, in terms of n, v, l, alpha) with the learner's `include` (a file of
// the work folder) at 2048 random normals, eyes and suns, after `set_uniforms`, and compares each
// value with `reference` within `tolerance` of the largest. With `fixed_sun`, l is that one
// direction (a chapter whose sun is a uniform); otherwise anywhere, below the surface too.
Verdict check_glsl(const fs::path& work, const std::string& include, const std::string& expression,
                   const Reference& reference, double tolerance, const SetUniforms& set_uniforms = {},
                   const glm::dvec3* fixed_sun = nullptr);

// Evaluates `expression` (GLSL, in terms of vec4 a and b, each component uniform in [low, high])
// at 2048 random inputs and compares it with `reference(a, b)`: for the wave functions of steps
// 01 to 05.
Verdict check_values(const fs::path& work, const std::string& include, const std::string& expression,
                     const ValueReference& reference, double tolerance, double low, double high,
                     const SetUniforms& set_uniforms = {});

// A vec3 (or, with components = 2, a vec2) `expression` held to `reference`, component by
// component as check_values does (x, then y, then z): the first component that fails is the verdict.
Verdict check_vector(const fs::path& work, const std::string& include, const std::string& expression,
                     const VectorReference& reference, double tolerance, double low, double high,
                     const SetUniforms& set_uniforms = {}, int components = 3);

// A C++ exercise's check: `driver` (C++ source, written beside the learner's file) is compiled with
// it by the compiler that built this tool, with the repository on the include path, and run with
// the number of cases as its argument, under a time limit (exercises/limits.hpp): it prints one
// line of numbers a case, read strictly (program_output.hpp). Each line is held to reference(case)
// within `tolerance` of the largest reference value; `cases` >= 1, every case the same count of values.
using CaseReference = std::function<std::vector<double>(int index)>;
Verdict check_cpp(const fs::path& work, const std::string& file, const std::string& driver, int cases,
                  const CaseReference& reference, double tolerance);

}  // namespace exercises
