// A teaching figure as ./ocean figures makes it: the numbers (NAME.dat) and the gnuplot script that
// draws NAME.png from them (NAME.gp), computed by the chapter's own code so that a figure cannot
// drift from what the chapter does. Each chapter's figures.cpp makes its figures with this; the
// figure tool (figure_data.cpp) writes them and gnuplot draws them. Shared by every chapter, it
// names none.
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

// A chapter's figures, each made when the tool asks for it (figure_data.cpp lists the chapters).
using FigureMakers = std::vector<Figure (*)()>;

}  // namespace figures
