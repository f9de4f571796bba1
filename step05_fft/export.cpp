#include "step05_fft/export.hpp"

#include "common/error.hpp"
#include "common/file_output.hpp"
#include "common/gl_texture.hpp"
#include "common/image.hpp"
#include "common/text.hpp"

#include <cstdio>
#include <filesystem>
#include <sstream>

namespace step05 {

namespace {
std::string exact(double value) {  // all 17 digits: the checker rebuilds the sea at this time
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return buffer;
}

// export.txt's line for one map: "file.height = height.pfm    # h, metres".
std::string file_line(const std::string& file, const std::string& meaning) {
    return "file." + file.substr(0, file.size() - 4) + " = " + file + "    # " + meaning + "\n";
}
}  // namespace

void export_maps(const std::string& dir, unsigned displacement_texture, unsigned slopes_texture, int layer,
                 int n, double patch_size, double time, double choppiness, const ocean::ParamRegistry& params) {
    // One layer of level 0: (l Dx, h, l Dz, l dDx/dz) and (dh/dx, dh/dz, l dDx/dx, l dDz/dz).
    const std::vector<float> displacement = ocean::read_texture_layer(displacement_texture, 0, layer, n);
    const std::vector<float> slopes = ocean::read_texture_layer(slopes_texture, 0, layer, n);
    write_export(dir, n, displacement, slopes, patch_size, time, choppiness, params,
                 {{"export.periodic", "1"}, {"export.origin_x", "0"}, {"export.origin_z", "0"}});
}

void write_export(const std::string& dir, int n, const std::vector<float>& displacement,
                  const std::vector<float>& slopes, double patch_size, double time, double choppiness,
                  const ocean::ParamRegistry& params, const std::vector<std::pair<std::string, std::string>>& notes,
                  const std::vector<ExtraMap>& extra) {
    const std::size_t texels = std::size_t(n) * n;
    std::vector<ocean::FloatImage> maps(std::size(kExportedMaps), ocean::FloatImage{n, n, std::vector<float>(texels)});
    for (std::size_t i = 0; i < texels; ++i) {
        const float* d = &displacement[4 * i];
        const float* s = &slopes[4 * i];
        maps[0].values[i] = d[1];
        maps[1].values[i] = d[0];
        maps[2].values[i] = d[2];
        maps[3].values[i] = s[0];
        maps[4].values[i] = s[1];
        maps[5].values[i] = (1 + s[2]) * (1 + s[3]) - d[3] * d[3];
    }
    // The maps first and export.txt last, each written whole: a folder with an export.txt holds
    // every map it names. The first file that cannot be written stops the export.
    const std::filesystem::path folder(dir);
    const auto save = [&folder](const ocean::FloatImage& map, const std::string& file) {
        if (auto error = ocean::save_pfm(map, (folder / file).string())) throw ocean::Error("--export: " + *error);
    };
    for (std::size_t m = 0; m < maps.size(); ++m) save(maps[m], kExportedMaps[m].file);
    for (const ExtraMap& map : extra) save(ocean::FloatImage{n, n, map.values}, map.file);
    std::ostringstream text;
    text << "# ocean maps: rows in each PFM go z = 0 first (PFM's bottom row), x = origin_x + i * patch_size / resolution\n";
    for (const auto& p : params.all()) text << p->name() << " = " << p->value_text() << "\n";
    text << "export.patch_size = " << ocean::format_number(patch_size) << "\n"
         << "export.resolution = " << n << "\n"
         << "export.time = " << exact(time) << "\n"
         << "export.choppiness = " << ocean::format_number(choppiness) << "\n";
    for (const auto& [key, value] : notes) text << key << " = " << value << "\n";
    for (const ExportedMap& map : kExportedMaps) text << file_line(map.file, map.meaning);
    for (const ExtraMap& map : extra) text << file_line(map.file, map.meaning);
    if (auto error = ocean::write_file(folder / "export.txt", text.str())) throw ocean::Error("--export: " + *error);
}

}  // namespace step05
