/* The global solver for granular scenes: every grain's move from one sparse system, the contact
 * stiffness assembled over all contacts (3 DOFs per grain, docs/method.md section 3), K dX = -F, solved
 * with CHOLMOD (symmetric), UMFPACK or PETSc (distributed) through linear.h; the symbolic analysis is reused while the candidate-pair
 * list (the sparsity pattern) stays the same. */
#ifndef GB_GLOBAL_H
#define GB_GLOBAL_H

#include "contact/pairs.h"
#include "gembem/scene.h"
#include "gembem/solver.h"
#include "gembem/status.h"

struct gb_sim;
typedef struct gb_global gb_global;

/* The system of n_grains grains and n_particles boundary particles, solved as the settings say (they
 * must outlive it: solver.linear, newton, petsc, global_alpha, max_move). */
gb_status gb_global_create(const gb_solver_settings *set, int n_grains, int n_particles, gb_global **out,
                           gb_error *err);
void gb_global_free(gb_global *gl);

/* Fills sim->scratch.dX for every grain. Grains outside the system (in_system[i] 0: fewer than two
 * contacts, src/solver/damped.c) move as in the reference iteration (cases b, c) and are held in the system; a rotation
 * without stiffness (kt = 0) or marked GB_IN_SYSTEM_NO_ROTATION is held;
 * the rest solve K dX = -F together, with the walls under stress control as DOFs of the same system
 * (their residual: force minus target). The diagonal is scaled by 1 + mu (Levenberg-Marquardt:
 * mu -> 0 is Newton's step, a large mu a short step along each DOF's own stiffness, like the
 * reference iteration). A move larger than `max_move` scales the whole step down.
 * Fills sim->scratch.wall_dx too. */
struct gb_wall_control_s;
gb_status gb_global_moves(gb_global *gl, struct gb_sim *sim, const unsigned char *in_system,
                          const struct gb_wall_control_s *wc, double mu, gb_error *err);

/* What the solver carries from one load step to the next (for checkpoints): the sliding contacts
 * that a solution unloaded, one flag per pair of P, while the sparsity pattern is P's; NULL when the
 * next move builds a new pattern (and starts with no flag set). */
const unsigned char *gb_global_unloading(const gb_global *gl, const gb_pair_set *P);
/* A resumed run: the flags (or NULL) that gb_global_unloading gave for P when the checkpoint was
 * written. The pattern and its analysis are built again at the next move. */
gb_status gb_global_resume(gb_global *gl, const gb_pair_set *P, const unsigned char *unloading, gb_error *err);

const gb_global_stats *gb_global_statistics(const gb_global *gl);

#endif
