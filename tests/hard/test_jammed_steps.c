/* Load steps on a jammed packing (300 discs relaxed frictionless by gb_jam, then friction 25 deg):
 * four steps of +5 % isotropic stress with each solver.
 *  - gb_jam's packing is in equilibrium: gembem's own fixing forces are below gb_jam's tolerance;
 *  - every solver converges to a = 100 dyn, the global solver in at most 60 iterations per step
 *    (a grain with a single contact once traded its force back and forth with the system: a
 *    two-cycle that took thousands of iterations, see gb_solver_mark_system in src/solver/damped.c);
 *  - the four solvers (the last: the global solver's line search, solver.newton: line_search) end
 *    at the same box (1e-5 relative: friction makes the answer depend
 *    slightly on the path, the sizes agree to the springs' deformation), CHOLMOD and UMFPACK to
 *    1e-8 cm (the corrections: conjugate gradients against a new factorisation);
 *    and the walls carry the target stress;
 *  - each relaxation's result (gb_solve_result) says it converged, within the accuracy, and its
 *    work sums to the solver's totals; a relaxation allowed one iteration stops at that cap.
 *   test_jammed_steps SCENE.yaml */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "gembem/gembem.h"

enum { N_SOLVERS = 4 };
static const char *const NAMES[N_SOLVERS] = {"reference", "global CHOLMOD", "global UMFPACK",
                                           "global line search"};

int main(int argc, char **argv)
{
    if (argc < 2) return fprintf(stderr, "usage: %s SCENE.yaml\n", argv[0]), 2;
    gb_box end[N_SOLVERS];
    for (int solver = 0; solver < N_SOLVERS; solver++) {
        gb_error err = {0};
        gb_scene sc;
        gb_sim *sim = NULL;
        CHECK(gb_scene_load(argv[1], &sc, &err) == GB_OK);
        sc.solver.method = solver ? GB_METHOD_GLOBAL : GB_METHOD_REFERENCE;
        sc.solver.linear = solver >= 2 ? GB_LINEAR_UMFPACK : GB_LINEAR_CHOLMOD;
        sc.solver.newton = solver == 3 ? GB_NEWTON_LINE_SEARCH : GB_NEWTON_DAMPED;
        CHECK(gb_sim_create(&sc, &sim, &err) == GB_OK);
        if (!sim) return fprintf(stderr, "%s\n", err.msg), 1;
        double s1, s2, worst = 0, F[3];
        gb_sim_stress(sim, &s1, &s2); /* and the forces */
        for (int i = 0; i < gb_sim_n_grains(sim); i++) {
            gb_sim_fixing_force(sim, i, F);
            for (int c = 0; c < 3; c++) worst = fmax(worst, fabs(F[c]));
        }
        CHECK(worst <= 1.0 * 1.01); /* gb_jam --tol 1 (per disc |F|; components are smaller) */
        double s0 = 0.5 * (s1 + s2);
        long most = 0;
        gb_solver_work sum = {0, 0, 0}; /* the results' work, each of its call alone */
        for (int k = 1; k <= 4; k++) {
            gb_wall_control wc = {GB_WALLS_STRESS, s0 * (1 + 0.05 * k), s0 * (1 + 0.05 * k), 0};
            gb_solve_result res;
            gb_status st = gb_solver_relax(sim, &wc, solver ? 500 : 100000, &res, &err);
            CHECK(st == GB_OK);
            if (st) fprintf(stderr, "%s step %d: %s (largest force %g)\n", NAMES[solver], k, err.msg, res.max_force);
            most = res.iterations > most ? res.iterations : most;
            CHECK(res.stop == GB_STOP_CONVERGED && res.max_force <= sc.solver.accuracy && res.seconds >= 0);
            sum.trials += res.work.trials, sum.factorisations += res.work.factorisations, sum.sweeps += res.work.sweeps;
            gb_sim_stress(sim, &s1, &s2);
            gb_box box = gb_sim_box(sim);
            double W = box.right - box.left;
            CHECK_NEAR(s1, wc.s1, 2 * sc.solver.accuracy / W);
            CHECK_NEAR(s2, wc.s2, 2 * sc.solver.accuracy / W);
        }
        /* the solver's own totals are the sum of its calls' results (none for the reference iteration) */
        gb_solver_work done = gb_solver_work_done(sim);
        CHECK(done.trials == sum.trials && done.factorisations == sum.factorisations && done.sweeps == sum.sweeps);
        CHECK(solver ? sum.trials >= 4 && sum.factorisations >= 4 : sum.trials == 0);
        end[solver] = gb_sim_box(sim);
        /* one more step of 5 %, one iteration allowed: stopped by the cap, which the result names */
        gb_wall_control more = {GB_WALLS_STRESS, s0 * 1.25, s0 * 1.25, 0};
        gb_solve_result capped;
        gb_status st = gb_solver_relax(sim, &more, 1, &capped, &err);
        CHECK(st == GB_ENOCONV && capped.stop == GB_STOP_ITERATIONS && capped.iterations == 1);
        CHECK(capped.max_force > sc.solver.accuracy);
        printf("%-18s: at most %ld iterations per step, box %.9f x %.9f\n", NAMES[solver], most,
               end[solver].right - end[solver].left, end[solver].top - end[solver].bottom);
        if (solver) CHECK(most <= 60);
        gb_sim_free(sim);
        gb_scene_free(&sc);
    }
    /* CHOLMOD solves its corrections by conjugate gradients on the previous factor, UMFPACK by a
     * new factorisation: the same system (no host: K is symmetric), the same answer to the
     * accuracy (a / kn = 1e-6 cm on a 13 cm box). */
    CHECK_NEAR(end[1].right - end[1].left, end[2].right - end[2].left, 1e-8);
    CHECK_NEAR(end[1].top - end[1].bottom, end[2].top - end[2].bottom, 1e-8);
    for (int solver = 1; solver < N_SOLVERS; solver++) {
        double W = end[0].right - end[0].left, H = end[0].top - end[0].bottom;
        CHECK_NEAR(end[solver].right - end[solver].left, W, 1e-5 * W);
        CHECK_NEAR(end[solver].top - end[solver].bottom, H, 1e-5 * H);
    }
    TEST_END();
}
