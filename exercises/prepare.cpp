#include "exercises/prepare.hpp"

#include <sstream>
#include <system_error>

#include "common/file_output.hpp"
#include "common/text.hpp"

namespace exercises {

std::optional<std::string> replace_body(const std::string& source, const std::string& signature,
                                        const std::string& stub) {
    std::istringstream in(source);
    std::ostringstream out;
    bool inside = false, found = false;
    for (std::string line; std::getline(in, line);) {
        if (!inside && !found && line == signature) {
            out << line << '\n' << stub << "}\n";
            inside = found = true;
            continue;
        }
        if (inside) {
            if (line == "}") inside = false;  // the function's closing brace, at column 0
            continue;
        }
        out << line << '\n';
    }
    if (!found) return std::nullopt;
    return out.str();
}

std::optional<std::string> prepare(const Exercise& exercise, const fs::path& work,
                                   const fs::path& source_root) {
    const bool cpp = is_cpp(exercise.file);
    const fs::path from = cpp ? source_root / exercise.step : source_root / exercise.step / "shaders";
    std::error_code error;
    fs::create_directories(work, error);
    if (error) return "cannot make the folder " + work.string() + ": " + error.message();
    if (fs::equivalent(work, from, error))
        return work.string() +
               " is the chapter's own folder: the learner's copy goes elsewhere (exercises/work/)";

    std::vector<fs::path> files;
    if (cpp) {
        files.push_back(from / exercise.file);
    } else {
        for (const auto& entry : fs::directory_iterator(from, error))
            if (entry.is_regular_file()) files.push_back(entry.path());
        if (error) return "cannot list " + from.string() + ": " + error.message();
    }
    const std::vector<Exercise> every = all();
    for (const fs::path& file : files) {
        std::string text;
        if (auto problem = ocean::read_text_file(file.string(), &text)) return "cannot read " + *problem;
        // The exercise's own function goes, and so does every other derived exercise's in the same
        // file: a derived answer is kept from every copy, not only from the pages.
        std::vector<const Exercise*> emptied;
        if (file.filename() == exercise.file) emptied.push_back(&exercise);
        for (const Exercise& other : every)
            if (other.derived && other.step == exercise.step && other.number != exercise.number &&
                file.filename() == other.file)
                emptied.push_back(&other);
        for (const Exercise* e : emptied) {
            const std::optional<std::string> stubbed = replace_body(text, e->signature, e->stub);
            if (!stubbed) return "'" + e->signature + "' is not a line of " + file.string();
            text = *stubbed;
        }
        if (auto problem = ocean::write_file(work / file.filename(), text)) return problem;
    }
    return std::nullopt;
}

}  // namespace exercises
