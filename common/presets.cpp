// Presets: a step's parameters as text, one `name = value` per line ('#' starts a comment, blank
// lines are ignored; README "Presets"), read whole and checked before any value is applied, and
// written with every parameter.
#include "common/params.hpp"

#include "common/file_output.hpp"
#include "common/text.hpp"

#include <sstream>
#include <string_view>

namespace ocean {

std::optional<std::string> ParamRegistry::apply_preset_text(const std::string& text,
                                                            const std::string& origin) {
    if (text.find('\0') != std::string::npos) return origin + ": not a text file";
    // Editors that save UTF-8 with a byte-order mark put EF BB BF before the first name.
    const std::string_view bom = "\xEF\xBB\xBF";
    std::istringstream lines(text.compare(0, bom.size(), bom) == 0 ? text.substr(bom.size()) : text);
    std::vector<std::pair<Param*, std::string>> assignments;
    std::string line;
    int number = 0;
    while (std::getline(lines, line)) {
        ++number;
        const std::string where = origin + ":" + std::to_string(number) + ": ";
        const std::string content = trim(line.substr(0, line.find('#')));
        if (content.empty()) continue;
        const auto eq = content.find('=');
        if (eq == std::string::npos || trim(content.substr(0, eq)).empty())
            return where + "expected 'name = value', got '" + ellipsize(content, 40) + "'";
        const std::string name = trim(content.substr(0, eq));
        const std::string value = trim(content.substr(eq + 1));
        Param* p = find(name);
        if (p == nullptr) return where + unknown_name_message(name);
        if (auto error = p->check_text(value)) return where + *error;
        assignments.emplace_back(p, value);
    }
    for (auto& [param, value] : assignments) param->set_from_text(value);
    return std::nullopt;
}

std::optional<std::string> ParamRegistry::load_preset(const std::string& path) {
    std::string text;
    if (auto error = read_text_file(path, &text)) return "cannot read preset " + *error;
    return apply_preset_text(text, path);
}

std::string ParamRegistry::preset_text(const std::string& header) const {
    std::ostringstream out;
    out << "# " << header << "\n"
        << "# One 'name = value' per line; '#' starts a comment. Missing names keep their\n"
        << "# defaults; unknown names and out-of-range values are refused.\n";
    std::string group;
    for (const auto& p : params_) {
        if (p->group() != group) {
            group = p->group();
            out << "\n# " << group << "\n";
        }
        out << p->name() << " = " << p->value_text() << "    # " << p->range_text() << " "
            << p->help() << "\n";
    }
    return out.str();
}

std::optional<std::string> ParamRegistry::save_preset(const std::string& path,
                                                      const std::string& header) const {
    // Whole or not at all: a preset cut short by a full disk would load as a different sea.
    return write_file(path, preset_text(header), "preset");
}

}  // namespace ocean
