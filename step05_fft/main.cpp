#include "common/app.hpp"
namespace {
class Fft : public ocean::App {
public:
    Fft() : App({"FFT ocean", "4.1-4.5", "wip"}) {}
    void render() override {}
};
}  // namespace
OCEAN_MAIN(Fft)
