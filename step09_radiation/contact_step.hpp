// Chapter 9, the contact: step08's wave field stepped with a body's push held to where its hull is.
// The field's response to a pressure is linear, so one step with pushes is the free step (step08's
// WaveField::step) plus what the pushes alone do to water at rest; the pushes are the ones that
// leave the surface at each contact point where the hull ends the step. This file finds them: the
// system between the points comes from the field's own response to a unit push on one cell (its
// kernel), taken by stepping a field at rest, so the contact needs nothing of the field's inside.
#pragma once

#include "step08_wakes/wave_field.hpp"

#include <memory>
#include <vector>

namespace step09 {

using step08::Complex;
using step08::times;
using step08::times_i;
using step08::Forcing;
using step08::WaveField;
using step08::WaveFieldSettings;

// Solves A x = b in place (b becomes x) for a symmetric positive definite A (m x m, row major),
// by Cholesky's factorisation A = L L^T (A is overwritten). Throws ocean::Error if A is not.
void solve_symmetric(std::vector<double>& a, std::vector<double>& b, std::size_t m);

// A body in contact with the water: at M points under its hull the surface must end each step
// where the hull is. Each point reads the field at `taps` cells with `weights` (one cell and
// weight 1: the cell's own height; four and bilinear weights: the surface between cell centres)
// and pushes on the same cells with the same weights, so that the push's work is the body's and
// the system stays symmetric. `cells` and `weights` hold taps entries a point (`weights` empty:
// all 1). The unknown at each point is its push, the force over the water's density (p / rho
// times the point's area, m^4/s^2), spread on its cells as a pressure.
// `target` is the height (m) the field must reach at each point if the body felt no push (the
// hull's underside, moved on by its own velocity and gravity, less the incident sea's height);
// `compliance`, M x M row major, how far the hull at point i moves in the step per unit push at
// point j: travel (1 / m + (r_i x y) . I^-1 (r_j x y)) with m and I per unit density (m^3, m^5)
// and travel the distance a step moves a body per unit acceleration (dt^2 for one step of
// semi-implicit Euler).
struct Contact {
    // Whether the water may only push (a hull resting on it, which can lift off) or also pull (a
    // hull held to the water, as linear theory's body is): pushing only, the points that would
    // need a pull are let go, and those the water would rise over taken in, until neither is left.
    bool push_only = false;
    int taps = 1;
    std::vector<std::size_t> cells;
    std::vector<double> weights;
    std::vector<double> target;
    std::vector<double> compliance;
};

class ContactStep {
public:
    // Steps `field` dt seconds (> 0) with `forcing` and `contact`: returns the pushes at its
    // points (one a point, held over the step; force / rho, m^4/s^2). The body's force is rho
    // times their sum, its torque their moments. The contact's points must lie clear of the
    // field's absorbing layer (where the water is damped, the hull would feel it).
    std::vector<double> step(WaveField& field, double dt, const Contact& contact, const Forcing& forcing = {});

    // The pressure p / rho (m^2/s^2) the last step's contact held on each cell (n * n; empty
    // before any). Under a steady push the field rests at -p / g: heights + p / g is what the
    // field holds beside that dent, its waves (what the program draws).
    const std::vector<double>& pressure() const { return pressure_; }
    // For a step taken without a contact: no pressure held.
    void release() { pressure_.clear(); }

private:
    // The height change a unit p / rho held on cell 0 over dt leaves on every cell, from rest (n x n,
    // periodic): a dent, -(1 - cos omega dt) / g mode by mode, so negative under the cell; the
    // field's kernel, made for `kernel_for_` seconds and `kernel_grid_`.
    void make_kernel(const WaveFieldSettings& settings, double dt);

    std::vector<double> kernel_, pressure_;
    double kernel_for_ = 0;
    WaveFieldSettings kernel_grid_;
    std::unique_ptr<WaveField> at_rest_;  // the field's grid and layer, at rest: the pushes' response
};

}  // namespace step09
