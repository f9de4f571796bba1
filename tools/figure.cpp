// The figures' shared look, their writing and the figure programs' main (figure.hpp), and the pass
// tables' lists (frame_path.hpp).
#include "tools/figure.hpp"
#include "tools/frame_path.hpp"

#include "common/file_output.hpp"

#include <cstdio>
#include <system_error>

namespace figures {

const char* const kStyle = R"gp(set terminal pngcairo size 900,540 font "DejaVu Sans,12" linewidth 1.5
set grid lc rgb "#dddddd"
set key top right box opaque
set border lc rgb "#444444"
set style line 1 lc rgb "#1f5fa8" lw 2
set style line 2 lc rgb "#d9822b" lw 2
set style line 3 lc rgb "#3a9a5b" lw 2
set style line 4 lc rgb "#a33b8f" lw 2
set style line 5 lc rgb "#777777" lw 1.5 dt 2
)gp";

Figure::Figure(const std::string& figure_name, const std::string& figure_folder)
    : name(figure_name), folder(figure_folder) {
    script << kStyle << "set output '" << name << ".png'\n";
}

std::optional<std::string> Figure::write(const std::filesystem::path& dir) const {
    const std::filesystem::path into = dir / folder;
    std::error_code error;
    std::filesystem::create_directories(into, error);
    if (error) return "cannot make " + into.string() + ": " + error.message();
    if (auto failure = ocean::write_file(into / (name + ".dat"), data.str())) return failure;
    return ocean::write_file(into / (name + ".gp"), script.str());
}

int run_main(int argc, char** argv, const FigureMakers& makers, const std::vector<std::string>& timers) {
    const std::string program = argc > 0 ? std::filesystem::path(argv[0]).filename().string() : "figures";
    if (argc == 2 && std::string(argv[1]) == "--timers") {
        if (timers.empty()) return std::fprintf(stderr, "%s: this chapter has no pass table\n", program.c_str()), 2;
        for (const auto& timer : timers) std::printf("%s\n", timer.c_str());
        return 0;
    }
    if (argc != 2 || std::string(argv[1]).rfind("--", 0) == 0) {  // an option it does not know is no folder
        const std::string usage = "usage: " + program + " OUT_DIR" + (timers.empty() ? "" : " | " + program + " --timers");
        return std::fprintf(stderr, "%s\n", usage.c_str()), 2;
    }
    const std::filesystem::path dir = argv[1];
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error) return std::fprintf(stderr, "%s: cannot make %s: %s\n", program.c_str(), argv[1], error.message().c_str()), 1;
    for (const auto make : makers)
        if (auto failure = make().write(dir)) return std::fprintf(stderr, "%s: %s\n", program.c_str(), failure->c_str()), 1;
    std::printf("%s: %zu figures' data and scripts in %s\n", program.c_str(), makers.size(), argv[1]);
    return 0;
}

std::vector<std::string> split_resources(std::string_view list) {
    std::vector<std::string> names;
    std::istringstream in{std::string(list)};
    for (std::string name; std::getline(in, name, ';');)
        if (!name.empty()) names.push_back(name);
    return names;
}

}  // namespace figures
