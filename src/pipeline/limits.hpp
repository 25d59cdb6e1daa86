// Size limits of a run ([limits], docs/conventions.md "Limits"): before a command allocates its
// large arrays it estimates their memory (bytes) and its work (time steps, sweep points,
// frequencies), and refuses a case beyond the limits with an InputError naming the case key that
// sets the size. The limits are a guard against runaway input (a typo of a few zeros), not a
// model of the run time: a user who means it raises them with limits.memory / limits.steps.
//
// Defaults (chosen here, the task left them open):
//   memory  half the machine's physical memory (sysconf(_SC_PHYS_PAGES) * page size / 2): the
//           run leaves the rest to the system and other users;
//   steps   1e6 per count: time steps of a run, points of a sweep, frequencies of an axis, of a
//           multiharmonic excitation or of the noise bands. The largest shipped cases use ~1e4.
//
// The estimates count what the pipelines keep (result arrays per step, point or frequency) and
// the dense matrices of the contact problem, so they are upper bounds of the same order as the
// measured peak memory (numbers in the function comments).
#pragma once

#include <string>

namespace rollnoise::pipeline {

struct ContactCase;

struct Limits {
  double memory = 0.0;   ///< bytes; 0: default_memory_limit()
  long steps = 1000000;  ///< time steps, sweep points or frequencies of one count

  double memory_bytes() const;
};

/// Half the machine's physical memory (bytes); 4 GiB when the system does not tell.
double default_memory_limit();

/// InputError naming `key` when `count` (of `what`, e.g. "time steps") exceeds limits.steps or
/// `bytes` (what they keep) exceeds the memory limit. Doubles, so that absurd inputs (2.9e13
/// steps) are compared without overflow; NaN counts as over the limit.
void check_size(const Limits& limits, const std::string& key, double count, const std::string& what,
                double bytes);

/// InputError naming `key` when `bytes` (needed by `what`) exceeds the memory limit.
void check_memory(const Limits& limits, const std::string& key, const std::string& what,
                  double bytes);

/// Memory of the contact problem on the case's grid (bytes), for the path the linear model takes
/// (solver.linear_model). Dense: the matrices over the grid elements that the tangential solvers
/// factorise (Newton Jacobian) and the linear model holds (K0 and its Cholesky factor), bounded by
/// 16 bytes x (grid elements)^2; measured peak memory of `rollnoise creep` on the paper case: 68x50
/// 126 MB (8.6 x n^2 above the 25 MB base), 96x70 348 MB (7.1 x n^2). Matrix-free (grids whose
/// reduced unknowns may exceed nss::kDenseReducedUnknowns): nss::linear_model_bytes, O(r x Krylov
/// basis) (200x200: ~1.5 GB estimated at r = 2n; bench --sweep-cost measures it).
double contact_bytes(const ContactCase& c);

/// Memory kept per time step by transient, response and validate (bytes): at most 20 doubles per
/// step (time, creepages, the forces of each solver, the normal load, element counts).
double transient_bytes(double steps);

/// Memory kept per point of a steady sweep (bytes): the point's case and its solution (tractions,
/// slip velocities and states: 33 bytes per grid element).
double sweep_bytes(const ContactCase& c, double points);

/// Memory kept per frequency by creep, noise and receptance (bytes): 4 KiB per frequency bounds
/// the creep and load coefficients, the wheel, rail and contact receptances (4x4 complex each)
/// and the forces of every loop variant.
double frequency_bytes(double frequencies);

/// check_size for the contact problem of a placed case: InputError naming grid.nx.
void check_contact_size(const ContactCase& c);

}  // namespace rollnoise::pipeline
