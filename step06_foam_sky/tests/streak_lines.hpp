// The streaks of a picture of the sea, measured as an observer measures them on a photograph: the
// lines of foam in it, how long, how wide and how far apart they are on the sea, which way they
// lie. Used by picture_check streaks.
//
// The picture's foam cover is read on a grid of the sea's mean level (each point through the
// camera's pinhole), 0.1 m a cell, along and across the wind, and averaged over kLineBlur metres
// along the wind (as an eye follows a line past the holes between its bubbles). Down each column
// of the grid (across the wind), a line's crossing is a peak of that cover from kLineCover up (and
// under a whitecap's kWhitecapCover: a whitecap is where a line starts, not part of it), standing
// kLineContrast above the lowest cover within kLineReach metres; its width is the run around it
// above half its height over that floor. A crossing continues the nearest line that was crossed
// within kLineGap metres upwind, kLineStep metres across for each metre along (a line wanders, a
// hole or a gap in it is jumped); one that continues none starts a line, as where a line splits
// from another. A line kLineLength metres long or longer counts.
#pragma once

#include "tests/picture_camera.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace step06_test {

constexpr double kLineCover = 0.12, kLineContrast = 0.08, kWhitecapCover = 0.6;  // foam cover
constexpr double kLineBlur = 2.0, kLineReach = 1.0, kLineGap = 3.0, kLineStep = 0.15, kLineLength = 2.0;  // metres

struct StreakFigures {
    int lines = 0;               // lines kLineLength or longer
    double metres_per_area = 0;  // their length on 1000 m^2 of sea
    double angle_deg = 0;        // their straight fits' angle from the wind, mean weighted by length
    double length_m = 0;         // median of the lines' lengths, weighted by length: the length of line a metre of line is in
    double width_m = 0;          // median of the widths at their crossings
    double spacing_m = 0;        // median distance across the wind between neighbouring lines
};

// cover: width x height values (row 0 at the top), -1 where the foam cannot be told from water.
// along, across: unit vectors on the sea, along the wind (where it blows to) and across it.
// half_side: the grid's half side, metres (the square must lie in the picture at any wind).
StreakFigures measure_streaks(const ocean_test::Pinhole& camera, int width, int height, const std::vector<double>& cover,
                              glm::dvec3 along, glm::dvec3 across, double half_side);

}  // namespace step06_test
