// step03's teaching figure, computed by the chapter's own normals.hpp on one of step02's waves:
// lighting_vectors.png, the tangent, the normal, the view, the light, the half vector and the
// mirror direction at one point of a wave, as the lighting model uses them.
#include "step03_lighting/figures.hpp"

#include "step02_sine3d/waves.hpp"
#include "step03_lighting/normals.hpp"

#include <vector>

namespace step03 {

namespace {

using figures::Figure;
const char* const kFolder = "step03_lighting";

// The vectors of the lighting model at a point of a wave (a cut through x, y): T, N from step03's
// normals.hpp, V to the eye, L to the sun, H halfway, R the reflection of V.
Figure lighting_vectors() {
    Figure f("lighting_vectors", kFolder);
    const std::vector<step02::DirectionalWave> waves{{0.0, 12.0, 1.0, 0.0}};  // along +x, 12 m, 1 m high
    f.data << "# x  height\n";
    for (int i = 0; i <= 300; ++i) {
        const double x = -10 + 20.0 * i / 300;
        f.data << x << ' ' << step03::height_and_gradient(waves, x, 0, 0).height << '\n';
    }
    const double x0 = 1.5;
    const step03::HeightGradient g = step03::height_and_gradient(waves, x0, 0, 0);
    const Vec3 t = step03::normalize(step03::tangent(g)), n = step03::normal(g);
    const Vec3 v = step03::normalize({-0.82, 0.57, 0}), l = step03::normalize({0.77, 0.64, 0});
    const Vec3 h = step03::normalize({v.x + l.x, v.y + l.y, v.z + l.z});
    // M, the sun mirrored about N: where a flat mirror along the surface sends the sunlight (Phong's R).
    const double ln = step03::dot(l, n);
    const Vec3 m{2 * ln * n.x - l.x, 2 * ln * n.y - l.y, 0};
    f.data << "\n\n# x y dx dy label\n";
    const double length = 3.0;
    const struct {
        const char* label;
        Vec3 d;
    } arrows[] = {{"T", t}, {"N", n}, {"V (to the eye)", v}, {"L (to the sun)", l}, {"H", h}, {"M", m}};
    for (const auto& a : arrows)
        f.data << x0 << ' ' << g.height << ' ' << length * a.d.x << ' ' << length * a.d.y << " \"" << a.label << "\"\n";
    f.script << R"gp(set title "The vectors of the lighting model at one point (step03's normals.hpp)"
set xlabel "x (m)"
set ylabel "y (m)"
set size ratio -1
set xrange [-6:8]
set yrange [-2:5]
unset key
plot 'lighting_vectors.dat' index 0 using 1:2 with lines ls 1, \
     '' index 1 using 1:2:3:4 with vectors head filled lw 2 lc rgb '#a33b8f', \
     '' index 1 using ($1+$3*1.12):($2+$4*1.12):5 with labels tc rgb '#222222'
)gp";
    return f;
}

}  // namespace

figures::FigureMakers teaching_figures() { return {lighting_vectors}; }

}  // namespace step03

int main(int argc, char** argv) { return figures::run_main(argc, argv, step03::teaching_figures()); }
