/* The grains and initial contact forces of a scene, inline or from CSV files. */
#ifndef GB_GRAINS_FILE_H
#define GB_GRAINS_FILE_H

#include "gembem/scene.h"
#include "scene/yaml_read.h"

/* Reads a `grains:` section (list / file / contacts) into s->grains and s->restart.contacts. */
gb_status gb_grains_section_read(gb_ymap *m, gb_scene *s, gb_error *err);
/* Reads a `box:` section. */
gb_status gb_box_read(gb_ymap *parent, gb_box *box, gb_error *err);
/* Checks that every initial contact overlaps (the grains themselves: src/scene/admit.c).
 * `where` names the file for the messages. */
gb_status gb_grains_check(const gb_scene *s, const char *where, gb_error *err);

/* "left", "right", "bottom", "top" -> GB_WALL_xxx, or -1. */
int gb_wall_from_name(const char *name);
const char *gb_wall_name(int wall);
/* The second side of a contact in files: a grain index, a wall name, or p<e> for boundary particle e. */
void gb_side_name(int j, char *buf, size_t n);

#endif
