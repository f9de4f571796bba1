// --export DIR: the simulated maps as float PFM files and DIR/export.txt, a `key = value` list of
// every parameter, the patch size, the resolution, the time and each file's name. Tests read it
// back (tests/export_check.cpp) and hold the maps to the CPU reference.
#pragma once

#include "common/params.hpp"

#include <string>
#include <utility>
#include <vector>

namespace step05 {

// Reads layer `layer` of the simulation's textures and writes the maps and export.txt into dir.
// Throws ocean::Error on failure.
void export_maps(const std::string& dir, unsigned displacement_texture, unsigned slopes_texture, int layer,
                 int resolution, double patch_size, double time, double choppiness,
                 const ocean::ParamRegistry& params);

// A map beyond the six above (a foam map, say), n x n, rows z first.
struct ExtraMap {
    std::string file, meaning;
    std::vector<float> values;
};

// Writes the maps from texel arrays laid out as the textures are, 4 floats a texel:
// (l Dx, h, l Dz, l dDx/dz) and (dh/dx, dh/dz, l dDx/dx, l dDz/dz). `notes` are extra
// `key = value` lines (a grid's origin and spacing, say). Each file is written whole
// (ocean::write_file), the maps first and export.txt last; the first that cannot be written throws
// ocean::Error naming it.
void write_export(const std::string& dir, int n, const std::vector<float>& displacement,
                  const std::vector<float>& slopes, double patch_size, double time, double choppiness,
                  const ocean::ParamRegistry& params, const std::vector<std::pair<std::string, std::string>>& notes,
                  const std::vector<ExtraMap>& extra = {});

// The maps written, in order, with the meaning each file has.
struct ExportedMap {
    const char* file;
    const char* meaning;
};
constexpr ExportedMap kExportedMaps[] = {
    {"height.pfm", "h, metres"},
    {"displacement_x.pfm", "choppiness * Dx, metres"},
    {"displacement_z.pfm", "choppiness * Dz, metres"},
    {"slope_x.pfm", "dh/dx"},
    {"slope_z.pfm", "dh/dz"},
    {"jacobian.pfm", "J = (1 + l dDx/dx)(1 + l dDz/dz) - (l dDx/dz)^2"},
};

}  // namespace step05
