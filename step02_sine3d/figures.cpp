// step02's teaching figures, computed by the chapter's own code (waves.hpp, wave_params.hpp and
// the framework's camera), so that the README's pictures show what the step draws:
// directional_wave.png (one wave seen from above: its crest lines, d and the wavelength) and
// camera_frustum.png (the view and projection matrices, from the side).
#include "step02_sine3d/figures.hpp"

#include "common/camera.hpp"
#include "common/constants.hpp"
#include "common/params.hpp"
#include "step02_sine3d/wave_params.hpp"
#include "step02_sine3d/waves.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace step02 {

namespace {

using figures::Figure;
constexpr double kPi = ocean::kPi;
const char* const kFolder = "step02_sine3d";

// step02: one directional wave seen from above (x to the right, z down the page, as the "top"
// camera shows it), its height from waves.hpp, its crest lines d.p = lambda (n + 1/4), which are
// perpendicular to d and lambda = 2 pi / w apart, and its direction d.
Figure directional_wave() {
    Figure f("directional_wave", kFolder);
    const DirectionalWave wave{30.0, 12.0, 1.0, 0.0};  // d at 30 degrees, 12 m, 1 m high
    const Direction d = direction(wave);
    const double lambda = 2 * kPi / angular_wavenumber(wave);
    f.data << "# x z height (t = 0)\n";
    for (int b = 0; b <= 400; ++b)
        for (int a = 0; a <= 400; ++a) {
            const double x = -20 + 0.1 * a, z = -20 + 0.1 * b;
            f.data << x << ' ' << z << ' ' << height({wave}, x, z, 0.0) << '\n';
        }
    f.data << "\n\n# crest lines: d.p = lambda (n + 1/4), where the height is the amplitude\n";
    for (int n = -4; n <= 3; ++n) {
        const double s = lambda * (n + 0.25);
        for (double u : {-40.0, 40.0}) f.data << s * d.x - u * d.z << ' ' << s * d.z + u * d.x << '\n';
        f.data << "\n";
        if (std::abs(height({wave}, s * d.x, s * d.z, 0.0) - wave.amplitude) > 1e-9)
            std::fprintf(stderr, "step02_sine3d_figures: directional_wave: a crest line misses the crest\n");
    }
    const double s0 = lambda * 0.25, side = -9.0;  // the wavelength's arrow, beside the origin
    f.data << "\n# x z dx dz: d (8 m long), then lambda between two crests\n"
           << "0 0 " << 8 * d.x << ' ' << 8 * d.z << '\n'
           << s0 * d.x + side * -d.z << ' ' << s0 * d.z + side * d.x << ' ' << lambda * d.x << ' ' << lambda * d.z << '\n';
    f.script << "set terminal pngcairo size 760,700 font \"DejaVu Sans,12\" linewidth 1.5\nset output 'directional_wave.png'\n"
             << "set title \"step02: one wave a sin(w d·(x, z) − tφ) seen from above (waves.hpp)\"\n"
             << "set xlabel \"x (m)\"\nset ylabel \"z (m), down the page: the view from above\"\n"
             << "set size ratio -1\nset xrange [-20:20]\nset yrange [20:-20]\nunset key\nunset grid\nset clip two\n"
             << "set palette defined (-1 '#0b2e59', 0 '#6fa8dc', 1 '#ffffff')\nset cblabel \"height (m)\"\nset cbrange [-1:1]\n"
             << "set style textbox opaque noborder\n"
             << "set label 1 \"d = (cos α, sin α), α = 30°\\ncrests travel along +d\" at " << 8.6 * d.x + 0.6 << ", "
             << 8.6 * d.z + 0.4 << " left front boxed tc rgb '#a33b8f'\n"
             << "set label 2 \"λ = 2π/w = " << std::lround(lambda) << " m\" at "
             << (s0 + 0.5 * lambda) * d.x + (side - 1.2) * -d.z << ", " << (s0 + 0.5 * lambda) * d.z + (side - 1.2) * d.x
             << " center front boxed tc rgb '#222222'\n"
             << "set label 3 \"crest lines: d·(x, z) = const,\\nperpendicular to d\" at -19, 18 left front boxed tc rgb '#d9822b'\n"
             << R"gp(plot 'directional_wave.dat' index 0 using 1:2:3 with image, \
     '' index 1 using 1:2 with lines lc rgb '#d9822b' lw 2.5, \
     '' index 2 every ::0::0 using 1:2:3:4 with vectors head filled size 1.2,20 lw 3 lc rgb '#a33b8f', \
     '' index 2 every ::1::1 using 1:2:3:4 with vectors heads filled size 0.8,20 lw 2 lc rgb '#222222'
)gp";
    return f;
}

// step02's camera from the side: the vertical plane through the eye and the target of the
// "overview" view (common/camera.cpp), the frustum's top and bottom edges from the inverse of
// projection * view, the eye's forward f and up u, and the sea of step02's default waves along the
// plane. Below: the depth the projection stores against the distance in front of the eye.
Figure camera_frustum() {
    Figure f("camera_frustum", kFolder);
    ocean::ParamRegistry registry;
    ocean::Camera camera;
    camera.declare_params(registry, ocean::camera_view("overview"));
    WaveParams sea;
    sea.declare(registry);
    const float aspect = 16.0f / 9.0f;
    const glm::mat4 view = camera.view(), projection = camera.projection(aspect);
    const glm::mat4 to_world = glm::inverse(projection * view);
    const glm::vec3 eye = camera.eye(), forward = camera.forward();
    const glm::vec3 heading = glm::normalize(glm::vec3(forward.x, 0, forward.z));
    const glm::vec3 up = glm::cross(glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0))), forward);
    // A point's coordinates in the figure: s along the heading from below the eye, and y.
    auto side = [&](glm::vec3 p) { return glm::vec2(glm::dot(p - eye, heading), p.y); };
    f.data << "# s  height of step02's default sea along the plane (t = 0)\n";
    for (int i = 0; i <= 830; ++i) {
        const double s = -36 + 0.2 * i;
        const glm::vec3 p = eye + heading * float(s);
        f.data << s << ' ' << height(sea.waves(), p.x, p.z, 0.0) << '\n';
    }
    // The frustum's top and bottom edges in this plane, from the eye through the far plane's points
    // (x_ndc = 0, y_ndc = -1 and 1, z_ndc = 1), cut where they leave the figure (s = 130, y = -6).
    const double s_max = 130, y_min = -6;
    const glm::vec2 eye_2d = side(eye), target_2d = side(glm::vec3(camera.target));
    glm::vec2 edge_end[2];
    double edge_angle[2];
    f.data << "\n\n# the frustum's edges in this plane: from the eye to where they leave the figure\n";
    for (int e = 0; e < 2; ++e) {
        const glm::vec4 p = to_world * glm::vec4(0.0f, e == 0 ? -1.0f : 1.0f, 1.0f, 1.0f);
        const glm::vec2 far_point = side(glm::vec3(p) / p.w), along = glm::normalize(far_point - eye_2d);
        const double reach = std::min(along.x > 0 ? (s_max - eye_2d.x) / along.x : 1e9,
                                      along.y < 0 ? (y_min - eye_2d.y) / along.y : 1e9);
        edge_end[e] = eye_2d + along * float(reach);
        edge_angle[e] = std::atan2(double(along.y), double(along.x)) * 180 / kPi;
        f.data << eye_2d.x << ' ' << eye_2d.y << '\n' << edge_end[e].x << ' ' << edge_end[e].y << "\n\n";
    }
    f.data << "\n# x y dx dy: f, u and the world's up (14 m long)\n"
           << eye_2d.x << ' ' << eye_2d.y << ' ' << 14 * glm::dot(forward, heading) << ' ' << 14 * forward.y << '\n'
           << eye_2d.x << ' ' << eye_2d.y << ' ' << 14 * glm::dot(up, heading) << ' ' << 14 * up.y << '\n'
           << eye_2d.x << ' ' << eye_2d.y << " 0 14\n";
    f.data << "\n\n# eye, target\n" << eye_2d.x << ' ' << eye_2d.y << '\n' << target_2d.x << ' ' << target_2d.y << '\n';
    f.data << "\n\n# distance in front of the eye (m)  depth stored, in [0, 1]\n";
    for (int i = 0; i <= 400; ++i) {
        const double distance = camera.near_plane * std::pow(double(camera.far_plane / camera.near_plane), i / 400.0);
        const glm::vec4 clip = projection * view * glm::vec4(eye + forward * float(distance), 1.0f);
        f.data << distance << ' ' << 0.5 * clip.z / clip.w + 0.5 << '\n';
    }
    const double n = camera.near_plane, far = camera.far_plane, half = 2 * far * n / (far + n);
    const glm::vec4 target_clip = projection * view * glm::vec4(glm::vec3(camera.target), 1.0f);
    const double target_depth = 0.5 * target_clip.z / target_clip.w + 0.5;
    const double distance = camera.distance, pitch = camera.pitch_deg, fov = camera.fov_deg;
    f.script << "set terminal pngcairo size 900,880 font \"DejaVu Sans,12\" linewidth 1.5\nset output 'camera_frustum.png'\n"
             << "set multiplot layout 2,1 title \"step02's camera (common/camera.cpp, the overview view): what the view and projection matrices do\"\n"
             << "set size ratio -1\nset xrange [-36:" << s_max << "]\nset yrange [" << y_min << ":50]\nunset key\nset clip two\n"
             << "set title \"from the side: the vertical plane through the eye and the target (fov " << fov << "°, pitch "
             << pitch << "°, distance " << distance << " m)\"\n"
             << "set xlabel \"metres along the view's heading\"\nset ylabel \"y (m)\"\n"
             << "set style textbox opaque noborder\n"
             << "set object 1 polygon from " << eye_2d.x << ',' << eye_2d.y << " to " << edge_end[0].x << ',' << edge_end[0].y
             << " to " << s_max << ',' << y_min << " to " << edge_end[1].x << ',' << edge_end[1].y << " to " << eye_2d.x << ','
             << eye_2d.y << " fc rgb '#d9822b' fs transparent solid 0.12 noborder\n"
             << "set object 2 circle at " << eye_2d.x << ',' << eye_2d.y << " size 28 arc [" << edge_angle[0] << ':'
             << edge_angle[1] << "] fs empty border lc rgb '#d9822b' lw 1.5 front\n"
             << "set label 1 \"eye\" at " << eye_2d.x - 2 << ", " << eye_2d.y - 2 << " right front boxed\n"
             << "set label 9 \"eye = target − distance · f\" at -34, 8 left front boxed\n"
             << "set label 2 \"target\" at " << target_2d.x << ", " << target_2d.y + 4.5 << " center front boxed\n"
             << "set label 3 \"f\" at " << eye_2d.x + 14 * glm::dot(forward, heading) + 1.5 << ", "
             << eye_2d.y + 14 * forward.y - 1.5 << " left front tc rgb '#a33b8f'\n"
             << "set label 4 \"u (the camera's up)\" at " << eye_2d.x + 14.5 * glm::dot(up, heading) + 1 << ", "
             << eye_2d.y + 14.5 * up.y << " left front boxed tc rgb '#1f5fa8'\n"
             << "set label 5 \"world up (0, 1, 0)\" at " << eye_2d.x - 1.5 << ", " << eye_2d.y + 13 << " right front boxed tc rgb '#777777'\n"
             << "set label 6 \"field of view " << fov << "° (vertical)\" at " << eye_2d.x + 30 << ", " << eye_2d.y - 14
             << " left front boxed tc rgb '#d9822b'\n"
             << "set label 7 \"near plane: " << n << " m from the eye\\nfar plane: " << far
             << " m along f, beyond the figure\" at " << s_max - 3 << ", 45 right front boxed font \",10\"\n"
             << "set label 8 \"the sea: step02's default waves\" at 100, -3.8 center front tc rgb '#0b2e59' font \",10\"\n"
             << R"gp(plot 'camera_frustum.dat' index 1 using 1:2 with lines lc rgb '#d9822b' lw 2, \
     '' index 0 using 1:2 with filledcurves y=-6 fc rgb '#6fa8dc' fs solid 0.5 noborder, \
     '' index 0 using 1:2 with lines ls 1, \
     '' index 2 every ::0::0 using 1:2:3:4 with vectors head filled lw 2.5 lc rgb '#a33b8f', \
     '' index 2 every ::1::1 using 1:2:3:4 with vectors head filled lw 2.5 lc rgb '#1f5fa8', \
     '' index 2 every ::2::2 using 1:2:3:4 with vectors head filled lw 1.5 dt 2 lc rgb '#777777', \
     '' index 3 using 1:2 with points pt 7 ps 1.4 lc rgb '#222222'
)gp"
             << "unset object 1\nunset object 2\nunset label\nset size noratio\nset autoscale\nset logscale x\nset format x \"10^{%L}\"\n"
             << "set xrange [" << n << ":" << far << "]\nset yrange [0:1.05]\n"
             << "set title \"the depth the projection stores, (z/w + 1)/2, against the distance in front of the eye\"\n"
             << "set xlabel \"distance along f (m), near plane to far plane\"\nset ylabel \"depth\"\n"
             << "set arrow 1 from " << half << ", graph 0 to " << half << ", graph 1 nohead ls 5\n"
             << "set label 1 \"half the depth values lie within " << std::round(half * 100) / 100
             << " m of the eye: 2 near far / (near + far)\" at " << half * 1.3 << ", 0.35 left boxed\n"
             << "set arrow 2 from " << distance << ", graph 0 to " << distance << ", graph 1 nohead ls 5 lc rgb '#a33b8f'\n"
             << "set label 2 \"the target, " << distance << " m: depth " << std::round(target_depth * 1e4) / 1e4
             << "\" at " << distance / 1.3 << ", 0.6 right boxed tc rgb '#a33b8f'\n"
             << "plot 'camera_frustum.dat' index 4 using 1:2 with lines ls 1\n"
             << "unset multiplot\n";
    return f;
}

}  // namespace

figures::FigureMakers teaching_figures() { return {directional_wave, camera_frustum}; }

}  // namespace step02

int main(int argc, char** argv) { return figures::run_main(argc, argv, step02::teaching_figures()); }
