#pragma once
// The stability bound of the water grid's semi-implicit (symplectic) Euler (docs/water.md).
//
// Linearized about rest, the grid's stiffness for a wave vector k is
//   K(k) = c * sum over the 8 neighbours r of e_r e_r^T (1 - cos(k.r)),
// e_r the unit spring direction. Its largest eigenvalue is 8c, reached at k = (pi, 0) (the edge
// springs along x give 4c, the four diagonals at 45 degrees another 4c), so the fastest mode has
// w^2 = 8c/m. Semi-implicit Euler with damping b = gamma/m on x'' = -w^2 x - b x' is stable when
//   w^2 dt^2 < 4 - 2 b dt,   i.e.   dt < (sqrt(b^2 + 4 w^2) - b) / w^2,
// which is 2/w without damping. Stretched springs (rest_ratio < 1) add transverse stiffness below
// c per spring, so 8c stays the bound for them too; a slack pre-tension (> 1) is softer still.
namespace pond::sim {

double stability_bound(double mass, double stiffness, double damping);

}  // namespace pond::sim
