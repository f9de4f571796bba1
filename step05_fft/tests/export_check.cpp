// export_check DIR [--flat]: reads what `step05_fft --export DIR` wrote, rebuilds the same sea on
// the CPU in double precision from export.txt's parameters and time, and holds every exported
// map to it: max |exported - reference| <= 1e-4 max |reference| (the Jacobian: on J - 1). With
// --flat it checks a calm sea instead: every map exactly flat (0, and J = 1). Exit 0 when all
// hold; otherwise one line per failure.
#include "common/image.hpp"
#include "common/params.hpp"
#include "common/text.hpp"
#include "step05_fft/export.hpp"
#include "step05_fft/ocean_maps.hpp"
#include "step05_fft/ocean_params.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

int main(int argc, char** argv) {
    if (argc < 2) return std::fprintf(stderr, "usage: export_check DIR [--flat]\n"), 2;
    const std::string dir = argv[1];
    const bool flat = argc > 2 && std::string(argv[2]) == "--flat";

    std::map<std::string, std::string> values;
    std::ifstream text(dir + "/export.txt");
    if (!text) return std::fprintf(stderr, "export_check: no %s/export.txt\n", dir.c_str()), 1;
    for (std::string line; std::getline(text, line);) {
        const std::string content = ocean::trim(line.substr(0, line.find('#')));
        const auto eq = content.find('=');
        if (eq != std::string::npos) values[ocean::trim(content.substr(0, eq))] = ocean::trim(content.substr(eq + 1));
    }
    ocean::ParamRegistry registry;
    step05::OceanParams ocean_params;
    ocean_params.declare(registry);
    for (const auto& [key, value] : values)
        if (registry.find(key) != nullptr)
            if (auto error = registry.set(key, value)) return std::fprintf(stderr, "export_check: %s\n", error->c_str()), 1;
    const double time = std::stod(values.at("export.time"));
    const double choppiness = std::stod(values.at("export.choppiness"));
    const step05::SpectrumParams params = ocean_params.spectrum;
    if (std::stoi(values.at("export.resolution")) != params.resolution)
        return std::fprintf(stderr, "export_check: resolution in export.txt disagrees with the parameter\n"), 1;

    const step05::OceanMaps reference = step05::simulate_cpu(step05::initial_spectrum(params), time);
    const std::size_t texels = reference[step05::Height].size();
    std::vector<std::vector<double>> expected(6, std::vector<double>(texels));
    for (std::size_t i = 0; i < texels; ++i) {
        expected[0][i] = reference[step05::Height][i];
        expected[1][i] = choppiness * reference[step05::DisplacementX][i];
        expected[2][i] = choppiness * reference[step05::DisplacementZ][i];
        expected[3][i] = reference[step05::SlopeX][i];
        expected[4][i] = reference[step05::SlopeZ][i];
        expected[5][i] = reference.jacobian(i, choppiness) - 1;  // compared around 1
    }
    int failures = 0;
    for (std::size_t m = 0; m < expected.size(); ++m) {
        const std::string file = step05::kExportedMaps[m].file;
        const std::string key = "file." + file.substr(0, file.size() - 4);
        if (values.count(key) == 0 || values[key] != file) {
            std::printf("FAIL: export.txt does not name %s\n", file.c_str());
            ++failures;
            continue;
        }
        std::string error;
        const auto image = ocean::load_pfm(dir + "/" + file, &error);
        if (!image || image->values.size() != texels) {
            std::printf("FAIL: %s\n", image ? (file + ": wrong size").c_str() : error.c_str());
            ++failures;
            continue;
        }
        double worst = 0, largest = 0;
        bool finite = true;
        for (std::size_t i = 0; i < texels; ++i) {
            const double got = image->values[i] - (m == 5 ? 1.0 : 0.0);
            finite = finite && std::isfinite(got);
            worst = std::max(worst, std::abs(got - expected[m][i]));
            largest = std::max(largest, std::abs(expected[m][i]));
        }
        const bool ok = finite && (flat ? worst == 0 && largest == 0 : worst <= 1e-4 * largest && largest > 0);
        std::printf("%s %-20s max |error| %.3g, max |value| %.3g\n", ok ? "ok  " : "FAIL", file.c_str(), worst, largest);
        if (!ok) ++failures;
    }
    std::printf("export_check: %d map(s) failed (t = %.17g, N = %d, %s)\n", failures, time, params.resolution,
                flat ? "flat sea expected" : "against the CPU reference");
    return failures == 0 ? 0 : 1;
}
