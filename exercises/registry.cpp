// The exercises the chapters register (each STEP/exercises.cpp, compiled into the tool: add_step's
// EXERCISES), gathered in step and number order.
#include <algorithm>
#include <tuple>

#include "exercises/exercise.hpp"

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
    std::sort(every.begin(), every.end(), [](const Exercise& a, const Exercise& b) {
        return std::tie(a.step, a.number) < std::tie(b.step, b.number);
    });
    return every;
}

bool is_cpp(const std::string& file) { return fs::path(file).extension() == ".cpp"; }

}  // namespace exercises
