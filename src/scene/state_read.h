/* A state file's host and solver sections (`initial_state:` of a scene). */
#ifndef GB_STATE_READ_H
#define GB_STATE_READ_H

#include "gembem/scene.h"
#include "scene/yaml_read.h"

/* The state's `host:` into s->restart.host, checked against s->host (read before): refused at the
 * state file's line and column when the element counts, the groups or their kinds of condition
 * differ, at the CSV's line and column when a particle is not on its element. A state without a
 * host is refused for a scene with one, and the other way round. */
gb_status gb_state_host_read(gb_ymap *state, gb_scene *s, gb_error *err);
/* Only the last check: a host in both or in neither (before the grains, whose contacts name
 * boundary particles or walls). */
gb_status gb_state_host_presence(gb_ymap *state, const gb_scene *s, gb_error *err);
/* The state's `solver_state:` (the global solver's damping), if any, into s->restart.solver. */
gb_status gb_state_solver_read(gb_ymap *state, gb_scene *s, gb_error *err);

/* Where a grain of a restarted hybrid run lies with the cavity at rest: moved back by the
 * displacement of its nearest boundary particle (checked as it stands, a grain by a wall that has
 * moved by more than its radius would lie in the host, and a long loading could not go on).
 * Without a host state, (x, y) itself. */
void gb_host_state_at_rest(const gb_host_state *hs, double x, double y, double out[2]);

#endif
