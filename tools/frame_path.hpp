// One frame's data path drawn from a chapter's own pass table (its frame_passes.hpp): the passes
// down the page in the order they run, every buffer and texture across it, and in each cell
// whether the pass reads it (blue), writes it (orange) or both. A table is an array of passes,
// each with the fields timer, program, reads and writes (resources separated by ';').
#pragma once

#include "tools/figure.hpp"

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

namespace figures {

// The names in a ';'-separated list of resources.
std::vector<std::string> split_resources(std::string_view list);

// The timers of a pass table, in the order they first run, each once: what --bench lists (a timer
// may time several passes, as step05's two fft passes).
template <class Passes>
std::vector<std::string> timed_passes(const Passes& passes) {
    std::vector<std::string> timers;
    for (const auto& pass : passes)
        if (std::find(timers.begin(), timers.end(), std::string(pass.timer)) == timers.end())
            timers.emplace_back(pass.timer);
    return timers;
}

template <class Passes>
Figure frame_path(const std::string& name, const std::string& folder, const std::string& title, const Passes& passes) {
    Figure f(name, folder);
    std::vector<std::string> resources;
    auto column = [&](const std::string& r) {
        for (std::size_t i = 0; i < resources.size(); ++i)
            if (resources[i] == r) return int(i);
        resources.push_back(r);
        return int(resources.size()) - 1;
    };
    for (const auto& pass : passes) {
        for (const auto& r : split_resources(pass.reads)) column(r);
        for (const auto& r : split_resources(pass.writes)) column(r);
    }
    const int rows = int(passes.size()), columns = int(resources.size());
    const int width = 780 + 66 * columns, height = 260 + 48 * rows;
    f.script << "set terminal pngcairo noenhanced size " << width << "," << height << " font \"DejaVu Sans,11\"\n"
             << "set output '" << name << ".png'\nunset key\nunset border\nunset tics\nunset grid\n"
             << "set label \"" << title << "\" at screen 0.5, screen " << 1.0 - 18.0 / height << " center font \",13\"\n"
             << "set lmargin at screen " << 620.0 / width << "\nset rmargin at screen " << 1.0 - 160.0 / width << "\n"
             << "set tmargin at screen " << 1.0 - 200.0 / height << "\nset bmargin at screen " << 40.0 / height << "\n"
             << "set xrange [-0.5:" << columns - 0.5 << "]\nset yrange [" << rows - 0.5 << ":-0.5]\n";
    int object = 1;
    for (int c = 0; c < columns; ++c)
        f.script << "set label \"" << resources[std::size_t(c)] << "\" at " << c << ", -0.75 rotate by 40 left font \",10\"\n";
    for (int r = 0; r < rows; ++r) {
        const auto& pass = passes[std::size_t(r)];
        f.script << "set label \"" << r + 1 << ". " << pass.timer << ": " << pass.program << "\" at screen "
                 << 10.0 / width << ", first " << r << " left font \",10\"\n";
        const auto reads = split_resources(pass.reads), writes = split_resources(pass.writes);
        for (int c = 0; c < columns; ++c) {
            const bool read = std::find(reads.begin(), reads.end(), resources[std::size_t(c)]) != reads.end();
            const bool written = std::find(writes.begin(), writes.end(), resources[std::size_t(c)]) != writes.end();
            const char* colour = read && written ? "#a33b8f" : written ? "#d9822b" : read ? "#1f5fa8" : "#f1f1f1";
            const char* mark = read && written ? "RW" : written ? "W" : read ? "R" : "";
            f.script << "set object " << object++ << " rect from " << c - 0.45 << ", " << r - 0.4 << " to " << c + 0.45
                     << ", " << r + 0.4 << " fc rgb '" << colour << "' fs solid noborder behind\n";
            if (*mark) f.script << "set label \"" << mark << "\" at " << c << ", " << r << " center tc rgb 'white' front\n";
        }
    }
    f.script << "set label \"R: the pass reads it   W: writes it   RW: both\" at screen " << 10.0 / width
             << ", screen " << 15.0 / height << " left\n"
             << "plot NaN\n";
    f.data << "# drawn from the pass table; no data\n";
    return f;
}

}  // namespace figures
