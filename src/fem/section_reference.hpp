// Reference values for checking the finite-element models against simple structures (the wheel's
// rim as a ring, a rail's foot as a cantilever plate strip): the properties of a polygonal section
// cut by a straight line, the in-plane flexural frequencies of a free ring (thin: Hoppe; thick:
// Timoshenko's curved beam with shear and rotary inertia), and the first frequency of a
// clamped-free plate strip of varying thickness in cylindrical bending. Used by tests/fem and
// tests/dynamics and docs/record/fe_wheel.md Sec. 1 and docs/record/waveguide_rail.md Sec. 2; no
// FE mesh is involved.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "fem/axisymmetric.hpp"

namespace rollnoise::fem {

/// Area properties of a plane polygon (coordinates (a, b), m): area, centroid and the second
/// moments about the centroid, i_aa = int (a - a_c)^2 dA, i_bb = int (b - b_c)^2 dA.
struct PlaneSectionProperties {
  double area = 0.0;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  double i_aa = 0.0;
  double i_bb = 0.0;
};

/// Area, centroid and second moments of a simple closed polygon (either orientation; last point not
/// repeated), by the shoelace-type formulas over its edges.
PlaneSectionProperties section_properties(const std::vector<Eigen::Vector2d>& polygon);

/// The part of a convex-or-not simple polygon where normal . p >= offset (Sutherland-Hodgman
/// against one half-plane; exact for the sections used here, whose cut is a single chord).
std::vector<Eigen::Vector2d> clip_half_plane(const std::vector<Eigen::Vector2d>& polygon,
                                             const Eigen::Vector2d& normal, double offset);

/// A ring: centroidal radius R (m), section area A (m^2), second moment I about the section's axis
/// parallel to the ring's axis (in-plane bending, m^4), shear coefficient kappa.
struct RingSection {
  double radius = 0.0;
  double area = 0.0;
  double second_moment = 0.0;
  double shear_coefficient = 5.0 / 6.0;
};

/// Cowper's shear coefficient of a rectangle, 10 (1 + nu) / (12 + 11 nu) (Cowper, J. Appl. Mech.
/// 33 (1966) 335-340).
double cowper_rectangle_shear_coefficient(double poisson_ratio);

/// In-plane flexural natural frequency (Hz) of a free thin ring with n >= 2 nodal diameters,
/// inextensional (Hoppe 1871; Love, A Treatise on the Mathematical Theory of Elasticity; Blevins,
/// Formulas for Natural Frequency and Mode Shape, 1979, the ring chapter):
///   omega_n^2 = E I / (rho A R^4) * n^2 (n^2 - 1)^2 / (n^2 + 1).
double thin_ring_inplane_frequency(const RingSection& ring, const IsotropicMaterial& material,
                                   int n);

/// The same for a thick ring: Timoshenko's curved beam (extension, shear and rotary inertia), the
/// lowest root of its 3x3 problem for (w, v, psi) = (W cos, V sin, Psi sin) n theta (w radial, v
/// circumferential, psi the section's rotation). Strains of the curved Timoshenko beam (as in Rao,
/// Vibration of Continuous Systems, Wiley 2007, the chapter on curved beams and rings; derived
/// here from the energies below, its thin limit checked against Hoppe's formula in the tests):
///   membrane eps = (v' + w)/R,  bending kappa = psi'/R,  shear gamma = (w' - v)/R - psi
/// energies per unit length E A eps^2/2, E I kappa^2/2, kappa_s G A gamma^2/2, kinetic
/// rho (A (v_t^2 + w_t^2) + I psi_t^2)/2. As h/R -> 0 it tends to thin_ring_inplane_frequency.
/// `foundation`: optional distributed springs on the ring (per unit length of its centre line):
/// radial k_r (N/m^2) on w, tangential k_t on v, and a mass per unit length added to w and v (e.g.
/// a wheel's web as radial strips clamped at the hub: k_r = E t / ((1 - nu^2) L), k_t = G t / L,
/// a third of the strips' mass rho t L; the strain energy k_r w^2/2 + k_t v^2/2).
struct RingFoundation {
  double radial_stiffness = 0.0;
  double tangential_stiffness = 0.0;
  double added_mass = 0.0;
};
double thick_ring_inplane_frequency(const RingSection& ring, const IsotropicMaterial& material,
                                    int n, const RingFoundation& foundation = {});

/// The cubic Hermite (Euler-Bernoulli) beam element of length le, DOFs (w_0, w'_0, w_1, w'_1):
/// stiffness EI/le^3 [12 6le -12 6le; ...] and consistent mass m le/420 [156 22le 54 -13le; ...]
/// (e.g. Przemieniecki, Theory of Matrix Structural Analysis, 1968).
struct BeamElement {
  Eigen::Matrix4d stiffness;
  Eigen::Matrix4d mass;
};
BeamElement hermite_beam_element(double bending_stiffness, double mass_per_length, double le);

/// First natural frequency (Hz) of a plate strip clamped at x = 0 and free at x = length, in
/// cylindrical bending (plane strain across its width: D = E h^3 / (12 (1 - nu^2)), mass rho h per
/// unit area), thickness h(x) (m) given as a function. Euler-Bernoulli elements with cubic Hermite
/// shape functions, `elements` of them (a uniform strip gives the cantilever's
/// 1.8751^2 sqrt(D / (rho h L^4)) / 2 pi, Blevins 1979, to 1e-6 with 40 elements; tested).
double cantilever_strip_frequency(const std::function<double(double)>& thickness, double length,
                                  const IsotropicMaterial& material, int elements = 40);

}  // namespace rollnoise::fem
