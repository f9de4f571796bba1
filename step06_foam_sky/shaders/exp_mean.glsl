// (1 - e^{-x}) / x, the mean of e^{-s x} over s in [0, 1], for the closed forms of foam_step.glsl
// and fog.glsl.
// By its series near x = 0, where float loses 1 - e^{-x} to cancellation (x = 0 has the limit 1).
#ifndef EXP_MEAN_GLSL
#define EXP_MEAN_GLSL
float mean_of_exp(float x) { return abs(x) > 1e-2 ? (1.0 - exp(-x)) / x : 1.0 - x * (0.5 - x / 6.0); }
#endif
