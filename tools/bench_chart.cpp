// bench_chart BENCH.csv OUT.png: one horizontal bar per step, stacked by pass (wall ms a frame),
// with the frames per second at its end. ./ocean bench calls it.
// CSV columns: step,size,fps,total_ms,passes, then the steps' extra figures (dft_ms, gpu_fft_ms, ...);
// passes is "name=ms;...". Only the first five are drawn.
#include "common/text.hpp"
#include "tools/canvas.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace {

struct Row {
    std::string step;
    double fps = 0, total = 0;
    std::vector<std::pair<std::string, double>> passes;
};

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) return std::fprintf(stderr, "usage: bench_chart BENCH.csv OUT.png\n"), 2;
    std::ifstream csv(argv[1]);
    if (!csv) return std::fprintf(stderr, "bench_chart: cannot read %s\n", argv[1]), 1;
    std::vector<Row> rows;
    std::string line;
    std::getline(csv, line);  // header
    while (std::getline(csv, line)) {
        const auto cells = ocean::split(line, ',');
        if (cells.size() < 5) continue;
        Row r;
        r.step = cells[0];
        r.fps = std::atof(cells[2].c_str());
        r.total = std::atof(cells[3].c_str());
        for (const auto& pass : ocean::split(cells[4], ';')) {
            const auto eq = pass.find('=');
            if (eq != std::string::npos) r.passes.emplace_back(pass.substr(0, eq), std::atof(pass.substr(eq + 1).c_str()));
        }
        rows.push_back(r);
    }
    if (rows.empty()) return std::fprintf(stderr, "bench_chart: no rows in %s\n", argv[1]), 1;

    // A pass keeps its colour in every chart (bench.png and sweep.png draw the same passes): the
    // known ones by name, any other from the spare colours in order of appearance.
    const std::map<std::string, ocean_tools::Colour> by_name{
        {"plot", {150, 150, 150}},      {"ocean", {86, 156, 214}},     {"simulation", {220, 140, 60}},
        {"foam", {110, 190, 110}},      {"sky", {100, 200, 200}},      {"background", {170, 130, 230}},
        {"bloom", {230, 200, 80}},      {"tonemap", {200, 90, 160}},   {"evolve", {180, 110, 60}},
        {"fft", {220, 90, 90}},         {"assemble", {90, 140, 60}}};
    const std::vector<ocean_tools::Colour> spare{{40, 110, 170}, {240, 170, 120}, {160, 200, 120}, {120, 120, 200}};
    std::map<std::string, ocean_tools::Colour> colours;
    std::vector<std::string> legend;
    std::size_t spares_used = 0;
    for (const auto& r : rows)
        for (const auto& [name, ms] : r.passes) {
            if (colours.count(name) != 0) continue;
            const auto known = by_name.find(name);
            colours[name] = known != by_name.end() ? known->second : spare[spares_used++ % spare.size()];
            legend.push_back(name);
        }

    double largest = 1;
    for (const auto& r : rows) largest = std::max(largest, r.total);
    int left = 190;  // room for the longest label (./ocean bench --sweep's are "step06 1920x1080")
    for (const auto& r : rows) left = std::max(left, 16 + ocean_tools::Canvas::text_width(r.step) + 12);
    const int bar_width = 600, bar = 26, gap = 14, top = 60;
    const int height = top + int(rows.size()) * (bar + gap) + 40 + 24 * int((legend.size() + 3) / 4);
    ocean_tools::Canvas canvas(left + bar_width + 260, height, {24, 27, 32});
    canvas.text(16, 16, "wall ms a frame, by pass (and frames per second)", {235, 238, 242}, 2);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const Row& r = rows[i];
        const int y = top + int(i) * (bar + gap);
        canvas.text(16, y + 6, r.step, {220, 224, 230}, 2);
        double x = left;
        for (const auto& [name, ms] : r.passes) {
            const double w = ms / largest * bar_width;
            canvas.fill_rect(int(x), y, std::max(1, int(w)), bar, colours[name]);
            x += w;
        }
        char label[64];
        std::snprintf(label, sizeof label, "%.1f ms, %.1f fps", r.total, r.fps);
        canvas.text(int(x) + 8, y + 6, label, {220, 224, 230}, 2);
    }
    int lx = 16, ly = top + int(rows.size()) * (bar + gap) + 16;
    for (const auto& name : legend) {
        canvas.fill_rect(lx, ly, 16, 16, colours[name]);
        canvas.text(lx + 22, ly + 2, name, {220, 224, 230}, 2);
        lx += 240;
        if (lx > left + bar_width) {
            lx = 16;
            ly += 24;
        }
    }
    if (auto error = ocean::save_png(canvas.image(), argv[2])) return std::fprintf(stderr, "bench_chart: %s\n", error->c_str()), 1;
    return 0;
}
