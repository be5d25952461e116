/* The scene of `gembem pack` (docs/packing.md): read by the granular scene's reader. */
#ifndef GB_SCENE_PACK_H
#define GB_SCENE_PACK_H

#include "gembem/scene.h"
#include "scene/yaml_read.h"

/* Reads the scene's own section (top: the scene's root mapping); mesh: the host's, or NULL for a box. */
typedef gb_status (*gb_scene_section_fn)(gb_ymap *top, gb_scene *s, const gb_bem_mesh *mesh, void *user,
                                         gb_error *err);

/* A pack scene: units, materials, box or host, body_force and solver exactly as a run scene's (the
 * same code, the same messages), and instead of grains, initial_state, loading and output its own
 * section, read by read_pack. Nothing is admitted (there are no grains yet). The host's mesh, if any,
 * is left in *mesh (the caller frees it with gb_bem_mesh_free; zeroed without a host). */
gb_status gb_scene_load_pack(const char *path, gb_scene *out, gb_bem_mesh *mesh, gb_scene_section_fn read_pack,
                             void *user, gb_error *err);

#endif
