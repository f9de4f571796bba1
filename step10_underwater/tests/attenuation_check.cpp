// attenuation_check: the seabed's colour through the water, measured from a picture and held to the
// chapter's closed form (water_light.hpp), channel by channel.
//
//   attenuation_check PICTURE.png WATER_TYPE SEABED_DEPTH EYE_DEPTH PITCH_DEGREES EXPOSURE
//
// The picture: a flat sea (wind 0), the sun overhead (sun_elevation 90), a white seabed
// (seabed_colour 1,1,1) without caustics, seen from EYE_DEPTH metres down looking PITCH degrees
// below the horizontal, no bloom, the tonemapper off (its values clamped, sRGB-encoded, not
// dithered) after EXPOSURE. The middle of the picture looks at the sand along d: the closed form
// gives its radiance, the sand's light (the sun's beam and the sky's, each attenuated on its way
// down) attenuated again over the path up to the eye, plus the water's own light over that path.
// Each channel the picture can resolve (above 2 % of full scale, below 95 %) must match within 5 %.
// Prints the figures; exit 0 when they hold, 1 otherwise, 2 on bad input.
#include "common/image.hpp"
#include "step06_foam_sky/look_params.hpp"
#include "step10_underwater/water_light.hpp"
#include "tests/picture_camera.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
    if (argc != 7) {
        std::fprintf(stderr, "usage: attenuation_check PICTURE.png WATER_TYPE SEABED_DEPTH EYE_DEPTH PITCH_DEGREES EXPOSURE\n");
        return 2;
    }
    std::string error;
    const auto image = ocean::load_image(argv[1], &error);
    if (!image) {
        std::fprintf(stderr, "attenuation_check: %s\n", error.c_str());
        return 2;
    }
    const step10::WaterType* water = step10::water_type_named(argv[2]);
    if (water == nullptr) {
        std::fprintf(stderr, "attenuation_check: no water type '%s'\n", argv[2]);
        return 2;
    }
    const double seabed = std::atof(argv[3]), eye = std::atof(argv[4]);
    const double pitch = std::atof(argv[5]) * 3.14159265358979323846 / 180, exposure = std::atof(argv[6]);

    step06::LookParams look;  // the program's defaults, the sun overhead
    look.sun_elevation = 90;
    const step10::WaterLight w = step10::water_light(*water, seabed, glm::dvec3(1.0), look);
    const glm::dvec3 d(std::cos(pitch), -std::sin(pitch), 0.0);  // only d.y and its length matter
    const glm::dvec3 predicted = exposure * step10::seabed_seen(w, eye, d, 1.0);

    // The middle 9 x 9 pixels, decoded to linear.
    glm::dvec3 measured(0.0);
    for (int y = image->height / 2 - 4; y <= image->height / 2 + 4; ++y)
        for (int x = image->width / 2 - 4; x <= image->width / 2 + 4; ++x)
            for (int c = 0; c < 3; ++c)
                measured[c] += ocean_test::srgb_to_linear(image->rgba[(std::size_t(y) * image->width + x) * 4 + c] / 255.0) / 81;

    int failures = 0, checked = 0;
    const char* names[3] = {"red", "green", "blue"};
    for (int c = 0; c < 3; ++c) {
        const bool resolved = predicted[c] > 0.02 && predicted[c] < 0.95;
        const double off = measured[c] / predicted[c] - 1;
        std::printf("attenuation_check: %s %s at %.0f m: predicted %.4f, measured %.4f (%+.1f %%)%s\n", argv[2],
                    names[c], seabed, predicted[c], measured[c], 100 * off, resolved ? "" : " (not resolved: not held)");
        if (!resolved) continue;
        ++checked;
        if (std::abs(off) > 0.05) ++failures;
    }
    if (checked == 0) std::printf("FAIL: no channel resolved (choose the exposure)\n");
    if (failures > 0) std::printf("FAIL: %d channel(s) off by more than 5 %%\n", failures);
    return checked > 0 && failures == 0 ? 0 : 1;
}
