// The horizon-clipped form factor of a spherical cap, for the "sphere" table of the LTC tables
// (assets/ltc/README.md): the arealight shaders approximate a polygon clipped to the horizon by the
// spherical cap with the same vector form factor F (Heitz 2017, "Geometric Derivation of the
// Irradiance of Polygonal Lights"). A cap of angular radius sigma has |F| = sin^2(sigma) and F points
// to its centre; its form factor clipped to the horizon is (1/pi) * integral over the cap of
// max(cos(theta), 0). This file computes that integral numerically (no closed form is used).
#pragma once

namespace rtlab::ltcfit {

// (1/pi) * integral over the cap of max(n.w, 0) dw, for the cap whose unclipped vector form factor
// has length `length` (0..1: sin^2 of its angular radius) and whose centre has n.c = z (-1..1).
double clippedCapFormFactor(double z, double length);

// The table's value: clippedCapFormFactor / length, with its limit max(z, 0) at length 0.
double sphereTableValue(double z, double length);

} // namespace rtlab::ltcfit
