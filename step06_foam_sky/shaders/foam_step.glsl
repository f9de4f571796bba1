// Chapter 5.3, one frame of foam at one texel (foam.hpp's foam_step is the CPU reference). The foam
// f obeys df/dt = q - r f: it is made at the rate q = injection * max(0, threshold - J) where the
// surface squeezes, and fades at the rate r. Held through the frame, q and r give the exact step
//     f(t + dt) = f e^{-r dt} + q (1 - e^{-r dt}) / r
// so the foam is the same at any frame rate.
float foam_step(float foam, float injection_rate, float decay_rate, float dt) {
    float x = decay_rate * dt;
    float decay = exp(-x);
    // (1 - e^{-x}) / x, by its series where float would lose it to cancellation (and at x = 0)
    float grown_fraction = x > 1e-2 ? (1.0 - decay) / x : 1.0 - x * (0.5 - x / 6.0);
    return clamp(foam * decay + injection_rate * dt * grown_fraction, 0.0, 1.0);
}
