// chou_hannaford.h: the geometric (virtual work) McKibben model of Chou & Hannaford
// (1996; used as the reference "Chou's model" by Pipan et al., Eq. (3)-(4) there).
// With inextensible braid fibres of length b wound n turns:
//   volume  V(L) = L (b^2 - L^2) / (4 pi n^2)
//   diameter D(L) = sqrt(b^2 - L^2) / (pi n)   (b sin(alpha) around n turns)
//   force   F(p, L) = -p dV/dL = p (3 L^2 - b^2) / (4 pi n^2)
// p is gauge pressure [Pa], L the braided length [m]. b and n follow from the initial
// length L0, diameter D0 and braid angle alpha0 (angle to the muscle axis):
//   b = L0 / cos(alpha0),  n = b sin(alpha0) / (pi D0).
// pamsim uses it as a physical plant and for the chamber volume V(l).
#pragma once

namespace pamsim {

struct BraidGeometry {
  double fibre_length_m = 0.0;  // b
  double turns = 0.0;           // n
};

// Throws InputError unless L0 > 0, D0 > 0 and 0 < alpha0 < 90 deg (radians here).
BraidGeometry braid_from_initial_shape(double length_m, double diameter_m, double braid_angle_rad);

double chou_hannaford_volume(const BraidGeometry& g, double length_m);
// The braid's diameter at length L (0 at the fully stretched L = b); for drawing the muscle.
double chou_hannaford_diameter(const BraidGeometry& g, double length_m);
double chou_hannaford_dvolume_dlength(const BraidGeometry& g, double length_m);
double chou_hannaford_force(const BraidGeometry& g, double p_pa, double length_m);

}  // namespace pamsim
