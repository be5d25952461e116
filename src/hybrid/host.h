/* The elastic host of a hybrid scene (METHOD.md sections 9-10; hybrid paper H 1-7): its boundary
 * meshed by gmsh, condensed by the boundary element module to the stiffness of its cavity,
 * F = K u + f0 (forces F = L t that the grains must put on the cavity's elements for element
 * displacements u), and the boundary particles that carry those DOFs. */
#ifndef GB_HOST_H
#define GB_HOST_H

#include "gembem/bem.h"
#include "gembem/scene.h"

typedef struct {
    gb_bem_mesh mesh;
    gb_bem_system sys;
    gb_bem_problem prob;
    gb_bem_stiffness K;  /* on the cavity group, in its element order */
    double *Ksym;        /* (K + K^t)/2, for the symmetric (CHOLMOD) solve */
    int cavity;          /* the cavity's group index */
    int m;               /* 2 x cavity elements */
    double *u;           /* element displacements, m */
    double *force;       /* K u + f0, m */
} gb_host;

/* Meshes, assembles and condenses the host; refuses a mesh or a condition it cannot use (GB_EINPUT). */
gb_status gb_host_create(const gb_host_def *def, gb_host **out, gb_error *err);
void gb_host_free(gb_host *h);
/* force = K u + f0 */
void gb_host_update_force(gb_host *h);
/* Moves a group with a displacement condition by (dx, dy) more and condenses again: K stays, f0
 * follows the new boundary values. */
gb_status gb_host_move_group(gb_host *h, const char *group, double dx, double dy, gb_error *err);
/* The force on a group (sum of traction x length over its elements) and its prescribed
 * displacement, for the current cavity displacements. */
gb_status gb_host_group_force(const gb_host *h, const char *group, double force[2], double disp[2], gb_error *err);
/* 1 if (x, y) lies in the cavity: not in the body, and within the cavity's bounding box. */
int gb_host_in_cavity(const gb_host *h, double x, double y);

#endif
