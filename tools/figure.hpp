// A teaching figure as ./ocean figures makes it: the numbers (NAME.dat) and the gnuplot script that
// draws NAME.png from them (NAME.gp), computed by the chapter's own code so that a figure cannot
// drift from what the chapter does. Each chapter's figures.cpp makes its figures with this and is
// its own small program (STEP_figures, whose main is run_main below); ./ocean figures runs every
// chapter's program and gnuplot draws the scripts. Shared by every chapter, it names none.
#pragma once

#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace figures {

// The look every figure shares: a white page, a light grid, the repository's blues.
extern const char* const kStyle;

// A figure's two files, built in memory and written whole once the figure is made. `folder` is
// where its picture belongs in the repository: the chapter that shows it (docs/figures for one
// several chapters show).
struct Figure {
    std::string name, folder;
    std::ostringstream data, script;
    Figure(const std::string& figure_name, const std::string& figure_folder);
    // DIR/FOLDER/NAME.dat, then NAME.gp beside it: the first one that cannot be written stops it,
    // with its message.
    std::optional<std::string> write(const std::filesystem::path& dir) const;
};

// A chapter's figures, each made when its program asks for it.
using FigureMakers = std::vector<Figure (*)()>;

// The main of a chapter's figure program, STEP_figures:
//   STEP_figures OUT_DIR   makes every figure of `makers` in turn and writes it into OUT_DIR/FOLDER;
//   STEP_figures --timers  prints `timers`, the timed passes of the chapter's pass table in the
//                          order they first run (frame_path.hpp's timed_passes): what the step's
//                          --bench must list (tests/smoke/frame_passes.sh). Only for a chapter
//                          that has a pass table.
// Its messages start with the program's name; the first file that cannot be written stops it.
int run_main(int argc, char** argv, const FigureMakers& makers, const std::vector<std::string>& timers = {});

}  // namespace figures
