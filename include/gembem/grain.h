/* The types that the contact law, scenes and simulations share: a contact type's material, the
 * box's walls, a grain, and how a contact names its other side. Types only: no module implements
 * this header, so that the lowest layer that needs them (src/contact) sees nothing above it. */
#ifndef GEMBEM_GRAIN_H
#define GEMBEM_GRAIN_H

/* Contact springs and strength of one contact type (K 3, 4, 13), and the optional rolling
 * resistance (docs/method.md section 3.1): kr = 0 leaves it out. */
typedef struct {
    double kn, kt;        /* normal and tangential spring stiffness [force/length] */
    double friction_deg;  /* Coulomb friction angle phi [degrees] */
    double cohesion;      /* c [force] */
    double kr;            /* rolling spring [force length / radian]; 0: no rolling resistance */
    double eta;           /* rolling limit |mr| <= eta R* pn [1] */
} gb_material;

enum { GB_WALL_LEFT = 0, GB_WALL_RIGHT = 1, GB_WALL_BOTTOM = 2, GB_WALL_TOP = 3, GB_N_WALLS = 4 };
/* The other side j of a contact (gb_contact, contacts files): a grain (j >= 0), a wall (j = -1 -
 * GB_WALL_xxx) or a host's boundary particle on cavity element e, j = GB_PARTICLE_J(e). */
#define GB_PARTICLE_J(e) (-1 - GB_N_WALLS - (e))
#define GB_IS_PARTICLE(j) ((j) < -GB_N_WALLS)
#define GB_PARTICLE_OF(j) (-1 - GB_N_WALLS - (j))

typedef struct {
    double left, right, bottom, top;
} gb_box;

typedef struct {
    double x, y, r;  /* centre and radius */
    double rot;      /* rotation [rad], counter-clockwise */
} gb_grain;

#endif
