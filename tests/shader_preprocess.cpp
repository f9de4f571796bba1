// shader_preprocess IN OUT: writes IN with its #includes expanded, exactly as the programs
// compile it, so that glslangValidator checks the same text the driver does.
#include "common/error.hpp"
#include "common/shader.hpp"

#include <cstdio>
#include <fstream>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: shader_preprocess IN OUT\n");
        return 2;
    }
    try {
        const auto source = ocean::preprocess_shader(argv[1], ocean::default_include_dirs());
        std::ofstream out(argv[2]);
        out << source.text;
        // The file table, for reading glslang's "ERROR: 0:12" messages back into file:line.
        for (std::size_t i = 0; i < source.files.size(); ++i)
            std::printf("%zu %s\n", i, source.files[i].c_str());
        return out ? 0 : 1;
    } catch (const ocean::Error& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
}
