// step07's teaching figure, computed by the chapter's own bodies (bodies.hpp, the code the window
// runs): push_and_steer.png, how far a right click carries each body against the drag's closed
// form, and the boat's track under the arrows.
#include "step07_buoyancy/figures.hpp"

#include "step07_buoyancy/bodies.hpp"
#include "step07_buoyancy/sea_surface.hpp"

#include <glm/geometric.hpp>
#include <sstream>
#include <vector>

namespace step07 {

namespace {

using figures::Figure;
const char* const kFolder = "step07_buoyancy";

// step07's controls on a flat sea at the defaults (bodies.hpp, the code the window runs): how far
// a right click carries each body (against d(t) = v (1 - e^-ct) / c, the linear drag's closed
// form), and the boat's track from above under the arrows.
Figure push_and_steer() {
    Figure f("push_and_steer", kFolder);
    const step07::FlatSea calm;
    constexpr double dt = 1.0 / 60;
    std::vector<step07::FloatingBody> bodies = step07::drop_bodies(step07::BodyParams{}, {0, 3, 0}, {1, 0});
    for (int i = 0; i < 15 * 60; ++i)  // settled first: 15 s is plenty on still water
        for (auto& body : bodies) body.step(calm, calm, dt);
    double speeds[3] = {};
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        step07::FloatingBody body = bodies[b];
        speeds[b] = step07::push_speed(body);
        const glm::dvec3 start = body.position();
        f.data << "# " << step07::kBodyNames[b] << ": t (s), distance (m) after a push at " << speeds[b] << " m/s\n";
        body.push(speeds[b] * body.mass() * glm::dvec3(0, 0, 1), body.position());
        for (int i = 0; i <= 3 * 60; ++i) {
            if (i % 3 == 0) f.data << i * dt << ' ' << body.position().z - start.z << '\n';
            body.step(calm, calm, dt);
        }
        f.data << "\n\n";
    }
    // The boat for 5 s: the up arrow alone, then the up and right arrows held together; in its own
    // frame at the start (ahead, and to its right: starboard).
    for (const double rudder : {0.0, 1.0}) {
        step07::FloatingBody boat = bodies[step07::kBoat];
        const glm::dvec3 start = boat.position();
        const glm::dvec3 ahead = boat.orientation() * glm::dvec3(1, 0, 0), right = boat.orientation() * glm::dvec3(0, 0, 1);
        f.data << "# the boat, up arrow" << (rudder > 0 ? " and right arrow" : "") << ": ahead, right (m) every 0.5 s\n";
        for (int i = 0; i <= 5 * 60; ++i) {
            const glm::dvec3 moved = boat.position() - start;
            if (i % 30 == 0) f.data << glm::dot(moved, ahead) << ' ' << glm::dot(moved, right) << '\n';
            step07::steer(boat, 1, rudder);
            boat.step(calm, calm, dt);
        }
        f.data << "\n\n";
    }
    const double c = step07::BodyParams{}.drag;
    const auto closed_form = [&](int b) {
        std::ostringstream e;
        e << speeds[b] << " * (1 - exp(-" << c << " * x)) / " << c;
        return e.str();
    };
    f.script << "set terminal pngcairo size 1000,440 font \"DejaVu Sans,12\" linewidth 1.5\nset output 'push_and_steer.png'\n"
             << "set multiplot layout 1,2 title \"step07's controls on a flat sea, at the defaults (bodies.hpp)\"\n"
             << "set title \"a right click: each body pushed its size (3 to 6 m) in 1 s\"\n"
             << "set xlabel \"time after the push (s)\"\nset ylabel \"distance (m)\"\nset xrange [0:3]\nset key bottom right\n"
             << "plot 'push_and_steer.dat' index 0 with lines ls 1 title \"buoy (1.2 m)\", \\\n"
             << "     '' index 1 with lines ls 2 title \"raft (5 m)\", \\\n"
             << "     '' index 2 with lines ls 3 title \"boat (9 m)\", \\\n"
             << "     " << closed_form(0) << " with lines ls 5 notitle, " << closed_form(1) << " with lines ls 5 notitle, \\\n"
             << "     " << closed_form(2) << " with lines ls 5 title \"v (1 − e^{−ct}) / c\"\n"
             << "set title \"the arrows held 5 s, seen from above (dots 0.5 s apart)\"\n"
             << "set xlabel \"ahead of the boat (m)\"\nset ylabel \"to its right (m)\"\nset autoscale\nset yrange [*:*] reverse\n"
             << "set size ratio -1\nset key bottom right\n"
             << "plot '' index 3 with linespoints ls 1 pt 7 ps 0.6 title \"↑\", \\\n"
             << "     '' index 4 with linespoints ls 2 pt 7 ps 0.6 title \"↑ and →\"\n"
             << "unset multiplot\n";
    return f;
}

}  // namespace

figures::FigureMakers teaching_figures() { return {push_and_steer}; }

}  // namespace step07

int main(int argc, char** argv) { return figures::run_main(argc, argv, step07::teaching_figures()); }
