/* The files written from the contacts of a step (io/contacts_file.h). */
#include "io/contacts_file.h"

#include <stdlib.h>

#include "io/file_util.h"

typedef struct {
    const gb_sim *sim;
    const gb_contact *c;
    int m;
    gb_contacts_writer *write;
} contacts_job;

static void write_job(FILE *f, const void *data)
{
    const contacts_job *j = data;
    j->write(f, j->sim, j->c, j->m);
}

gb_status gb_contacts_file_write(const char *path, const gb_sim *sim, gb_contacts_writer *write, gb_error *err)
{
    int m;
    gb_contact *c = gb_sim_contacts_copy(sim, &m, err);
    if (!c) return err->code;
    contacts_job job = {sim, c, m, write};
    gb_status st = gb_atomic_write(path, write_job, &job, err);
    free(c);
    return st;
}

void gb_contact_far_end(const gb_sim *sim, const gb_contact *c, double *x, double *y)
{
    gb_grain gi = gb_sim_grain(sim, c->i);
    if (c->j >= 0) {
        gb_grain gj = gb_sim_grain(sim, c->j);
        *x = gj.x, *y = gj.y;
    } else {
        *x = gi.x + c->nx * (gi.r - c->overlap);
        *y = gi.y + c->ny * (gi.r - c->overlap);
    }
}
