// What a step's --export wrote (export.txt and its PFM maps), as the tools that check from outside
// the code read it (physics_check, picture_check): they know the file formats, nothing else.
#pragma once

#include "common/image.hpp"
#include "common/text.hpp"

#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace ocean_test {

struct Export {
    std::map<std::string, std::string> values;
    int n = 0;
    double extent = 0, time = 0;
    bool periodic = true;
    std::vector<double> map(const std::string& dir, const std::string& file) const {
        std::string error;
        const auto image = ocean::load_pfm(dir + "/" + file, &error);
        if (!image || image->width != n || image->height != n) throw std::runtime_error(dir + "/" + file + ": " + error);
        return {image->values.begin(), image->values.end()};
    }
};

inline Export read_export(const std::string& dir) {
    Export e;
    std::ifstream text(dir + "/export.txt");
    if (!text) throw std::runtime_error("no " + dir + "/export.txt");
    for (std::string line; std::getline(text, line);) {
        const std::string content = ocean::trim(line.substr(0, line.find('#')));
        const auto eq = content.find('=');
        if (eq != std::string::npos) e.values[ocean::trim(content.substr(0, eq))] = ocean::trim(content.substr(eq + 1));
    }
    e.n = std::stoi(e.values.at("export.resolution"));
    e.extent = std::stod(e.values.at("export.patch_size"));
    e.time = std::stod(e.values.at("export.time"));
    e.periodic = e.values.count("export.periodic") == 0 || e.values.at("export.periodic") == "1";
    return e;
}

// A value of export.txt as a number (a parameter, or one of export.*).
inline double number(const Export& e, const std::string& key) {
    const auto found = e.values.find(key);
    if (found == e.values.end()) throw std::runtime_error("export.txt has no " + key);
    return std::stod(found->second);
}

}  // namespace ocean_test
