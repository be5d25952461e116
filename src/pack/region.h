/* The region a packing fills: a box of walls, or the cavity of a host's mesh with its boundary
 * particles (half-discs on the cavity's elements, bulging into it). */
#ifndef GB_PACK_REGION_H
#define GB_PACK_REGION_H

#include "gembem/scene.h"

typedef struct {
    const gb_box *box;        /* the walls, or NULL */
    const gb_bem_mesh *mesh;  /* the host's mesh, or NULL */
    int cavity;               /* its cavity group */
    double lo[2], hi[2];      /* bounding box */
    double area;              /* the box's, or the cavity polygon's (shoelace) */
    double margin;            /* the boundary particles' largest radius (half the longest element); 0: a box */
} gb_region;

/* The scene's box, or the cavity of mesh (non-NULL with a host). */
void gb_region_init(gb_region *rg, const gb_scene *s, const gb_bem_mesh *mesh);
/* 1 if a disc of radius r at (x, y) lies in the region clear of its walls; in a cavity also clear
 * of every boundary particle (at least r + margin from the polygon). */
int gb_region_fits(const gb_region *rg, double x, double y, double r);

#endif
