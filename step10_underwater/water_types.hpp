// The water types the panel offers (`water_type`): each an absorption a and a scattering b per
// colour channel (1/m), and the asymmetry g of the scattering's phase function. water_colour.hpp
// says where each number comes from and is their CPU reference.
#pragma once

#include <glm/vec3.hpp>

#include <array>

namespace step10 {

struct WaterType {
    const char* name;
    glm::vec3 absorption;  // a, 1/m: red, green, blue
    glm::vec3 scattering;  // b, 1/m
    float phase_g;         // Henyey-Greenstein: 0 even, towards 1 forward
};

// PROVISIONAL until water_colour.hpp's cited values replace them (not to be committed as is).
inline constexpr std::array<WaterType, 2> kWaterTypes = {{
    {"clear_ocean", {0.45f, 0.065f, 0.015f}, {0.002f, 0.004f, 0.008f}, 0.3f},
    {"coastal", {0.5f, 0.12f, 0.12f}, {0.15f, 0.18f, 0.2f}, 0.9f},
}};

}  // namespace step10
