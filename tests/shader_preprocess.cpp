// shader_preprocess [--profile 450|410|300es] IN OUT: writes IN with its #includes expanded,
// exactly as a build of that profile compiles it (default 450, the GL 4.5 build), so that
// glslangValidator checks the same text the driver does. Prints the file table ("N path"), then
// each binding the profile moved to the host ("binding NAME UNIT").
#include "common/error.hpp"
#include "common/shader.hpp"

#include <cstdio>
#include <cstring>
#include <fstream>

int main(int argc, char** argv) {
    ocean::GlProfile profile = ocean::GlProfile::Core45;
    if (argc == 5 && std::strcmp(argv[1], "--profile") == 0) {
        const std::string name = argv[2];
        if (name == "450") profile = ocean::GlProfile::Core45;
        else if (name == "410") profile = ocean::GlProfile::Core41;
        else if (name == "300es") profile = ocean::GlProfile::Es30;
        else return std::fprintf(stderr, "shader_preprocess: unknown profile '%s' (450, 410, 300es)\n", argv[2]), 2;
        argv += 2;
        argc -= 2;
    }
    if (argc != 3) {
        std::fprintf(stderr, "usage: shader_preprocess [--profile 450|410|300es] IN OUT\n");
        return 2;
    }
    try {
        const auto source = ocean::preprocess_shader(argv[1], ocean::default_include_dirs(), {}, profile);
        std::ofstream out(argv[2]);
        out << source.text;
        // The file table, for reading glslang's "ERROR: 0:12" messages back into file:line.
        for (std::size_t i = 0; i < source.files.size(); ++i)
            std::printf("%zu %s\n", i, source.files[i].c_str());
        for (const auto& b : source.bindings) std::printf("binding %s %d\n", b.name.c_str(), b.unit);
        return out ? 0 : 1;
    } catch (const ocean::Error& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
}
