/* The files written from the contacts of a step: the state's CSV and the VTK snapshot. */
#ifndef GB_IO_CONTACTS_FILE_H
#define GB_IO_CONTACTS_FILE_H

#include <stdio.h>

#include "gembem/gem.h"

/* Prints a file of the m force-carrying contacts c of sim. */
typedef void gb_contacts_writer(FILE *f, const gb_sim *sim, const gb_contact *c, int m);

/* path written whole (io/file_util's atomic files) by write, from a copy of sim's contacts. */
gb_status gb_contacts_file_write(const char *path, const gb_sim *sim, gb_contacts_writer *write, gb_error *err);

/* The far end of a contact of grain c->i for drawing force chains: grain j's centre, or the
 * contact point on a wall or a boundary particle. */
void gb_contact_far_end(const gb_sim *sim, const gb_contact *c, double *x, double *y);

#endif
