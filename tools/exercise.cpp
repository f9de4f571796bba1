// exercise prepare STEP N WORK_DIR | exercise check STEP N WORK_DIR | exercise list
// exercise hint STEP N | exercise flags STEP N
// The exercises behind ./ocean exercise and ./ocean check (exercises/README.md).
//   prepare: copies the step's shaders into WORK_DIR and empties one function there (its body
//            becomes a TODO that compiles), so the step runs on the learner's copy
//            (--shader-dir, hot reload) with that piece missing.
//   check:   compiles the learner's function on the GPU, evaluates it at many inputs and holds it
//            to the chapter's CPU reference; prints pass, or fail with a hint. Exit 0 on pass.
//   hint:    the formula the task leaves out (the second hint: try first, then read it).
//   flags:   the step's flags that run the code the exercise edits, one a line (./ocean passes them).
// The solutions are the chapters' own shaders: an exercise removes a piece of working code.
#include "tools/exercise.hpp"

#include "common/context.hpp"
#include "common/error.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace exercises {

namespace {
std::vector<std::vector<Exercise> (*)()>& chapters() {
    static std::vector<std::vector<Exercise> (*)()> registered;  // filled before main() runs
    return registered;
}
}  // namespace

Registration::Registration(std::vector<Exercise> (*chapter)()) { chapters().push_back(chapter); }

std::vector<Exercise> all() {
    std::vector<Exercise> every;
    for (auto* chapter : chapters())
        for (Exercise& e : chapter()) every.push_back(std::move(e));
    std::sort(every.begin(), every.end(),
              [](const Exercise& a, const Exercise& b) { return std::tie(a.step, a.number) < std::tie(b.step, b.number); });
    return every;
}

}  // namespace exercises

namespace {

using namespace exercises;

const Exercise* find(const std::string& step, int number) {
    static const std::vector<Exercise> every = all();
    for (const Exercise& e : every)
        if (e.step == step && e.number == number) return &e;
    return nullptr;
}

// The step's shaders copied into `work`, with the exercise's function body replaced by its stub.
void prepare(const Exercise& e, const fs::path& work) {
    fs::create_directories(work);
    if (is_cpp(e.file)) {  // a C++ exercise: that file alone, from the step's folder
        fs::copy_file(fs::path(OCEAN_SOURCE_DIR) / e.step / e.file, work / e.file, fs::copy_options::overwrite_existing);
    } else {
        const fs::path source = fs::path(OCEAN_SOURCE_DIR) / e.step / "shaders";
        for (const auto& entry : fs::directory_iterator(source))
            if (entry.is_regular_file())
                fs::copy_file(entry.path(), work / entry.path().filename(), fs::copy_options::overwrite_existing);
    }
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
    std::fprintf(stderr, "usage: exercise list | exercise prepare|check STEP N WORK_DIR | exercise hint|flags STEP N\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const std::string verb = argc > 1 ? argv[1] : "";
        if (verb == "list" && argc == 2) {
            for (const Exercise& e : all()) std::printf("%s %d  %s (%s)\n", e.step.c_str(), e.number, e.title.c_str(), e.file.c_str());
            return 0;
        }
        const bool takes_work = verb == "prepare" || verb == "check";
        if (!(takes_work && argc == 5) && !((verb == "hint" || verb == "flags") && argc == 4)) return usage();
        const Exercise* e = find(argv[2], std::atoi(argv[3]));
        if (e == nullptr) {
            std::fprintf(stderr, "exercise: no exercise %s of %s (exercise list names them)\n", argv[3], argv[2]);
            return 2;
        }
        if (verb == "hint") {
            std::printf("exercise %d of %s: %s\n%s\n", e->number, e->step.c_str(), e->title.c_str(), e->formula.c_str());
            return 0;
        }
        if (verb == "flags") {
            for (const std::string& flag : e->run_flags) std::printf("%s\n", flag.c_str());
            return 0;
        }
        const fs::path work = argv[4];
        if (verb == "prepare") {
            prepare(*e, work);
            std::printf("exercise %d of %s: %s\n%s\nedit %s %s\nstuck? ./ocean exercise %s %d --hint prints the formula\n",
                        e->number, e->step.c_str(), e->title.c_str(), e->task.c_str(), (work / e->file).string().c_str(),
                        is_cpp(e->file) ? "(C++: ./ocean check holds it to the chapter's own)"
                                        : "(the step reloads it when you save)",
                        e->step.c_str(), e->number);
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
