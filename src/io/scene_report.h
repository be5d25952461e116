/* What the reading of a scene found, for run_info.yaml: its geometric admission and its host's mesh. */
#ifndef GB_SCENE_REPORT_H
#define GB_SCENE_REPORT_H

#include <stdio.h>

#include "gembem/scene.h"

/* YAML lines: `admission:` (overlaps accepted), `host_mesh:` (elements per group, the cavity's
 * shortest and longest element against the grains' mean radius) and `warning:` when there is one. */
void gb_scene_report_write(FILE *f, const gb_scene *s);
/* `key: "text"`, the text's double quotes turned to single ones (run_info.yaml's messages). */
void gb_info_quoted(FILE *f, const char *key, const char *text);

#endif
