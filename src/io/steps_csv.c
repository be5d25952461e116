/* steps.csv: the load-displacement path and each step's error. */
#include "io/steps_csv.h"

#include "io/file_util.h"

#include <math.h>

void gb_steps_csv_header(FILE *f)
{
    fprintf(f, "step,stage,e1_minus_e2,e1,e2,ev,s1,s2,stress_ratio,iterations,max_fixing_force,seconds,"
               "contacts,width,height,substeps,trials,factorisations,sweeps,force_scale,accuracy,relative_residual,"
               "relative_wall_residual,host_balance,coulomb_excess,mean_normal_force,coordination,rattlers,stop,"
               "sweeps_per_iteration\n");
}

/* a force over the step's force scale; undefined without one */
static double relative(double force, const gb_step_report *r)
{
    return r->force_scale > 0 ? force / r->force_scale : NAN;
}

void gb_steps_csv_row(FILE *f, const gb_step_report *r)
{
    fprintf(f, "%d,%d,", r->step, r->stage + 1);
    const double box_path[] = {r->e1 - r->e2, r->e1, r->e2, r->ev, r->s1, r->s2, r->stress_ratio};
    for (int k = 0; k < 7; k++) gb_csv_put(f, k ? ",%.10e" : "%.10e", box_path[k]);
    fprintf(f, ",%ld,%.6e,%.6e,%d,", r->iterations, r->max_fixing_force, r->seconds, r->n_contacts);
    gb_csv_put(f, "%.17g", r->width);
    gb_csv_put(f, ",%.17g", r->height);
    fprintf(f, ",%d,%ld,%ld,%ld,%.17g,%.17g", r->substeps, r->work.trials, r->work.factorisations, r->work.sweeps,
            r->force_scale, r->accuracy);
    const double rel[] = {relative(r->max_fixing_force, r), relative(r->wall_residual, r),
                          relative(r->max_particle_force, r), relative(r->coulomb_excess, r)};
    for (int k = 0; k < 4; k++) gb_csv_put(f, ",%.6e", rel[k]);
    fprintf(f, ",%.10e,%.6f,%d", r->mean_normal_force, r->coordination, r->rattlers);
    /* why the step was cut back ("converged": it was not); the smoother's steps per iteration */
    fprintf(f, ",%s,%.6g\n", gb_solve_stop_name(r->cut_by),
            r->iterations > 0 ? (double)r->work.sweeps / (double)r->iterations : 0.0);
}
