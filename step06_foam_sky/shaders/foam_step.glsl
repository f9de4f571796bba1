// Chapter 5.3, one frame of foam at one texel (foam.hpp's foam_step is the CPU reference). The foam
// f obeys df/dt = q - r f: it is made at the rate q = injection * max(0, threshold - J) where the
// surface squeezes, and fades at the rate r. Held through the frame, q and r let the equation be
// solved exactly over the frame rather than stepped (foam.md, section 3), so the foam is the same
// at any frame rate. foam.frag takes it at two rates: the active foam's and the foam's as a whole.
#include "exp_mean.glsl"

float foam_step(float foam, float injection_rate, float decay_rate, float dt) {
    float x = decay_rate * dt;
    return clamp(foam * exp(-x) + injection_rate * dt * mean_of_exp(x), 0.0, 1.0);
}
