/* The registry of linear solvers: the backends that core/config.h's GB_LINEAR_SOLVERS lists. */
#include <stddef.h>

#include "solver/linear.h"

#define GB_LINEAR_ENTRY(name) &gb_linear_##name,
static const gb_linear_backend *const BACKENDS[] = {GB_LINEAR_SOLVERS(GB_LINEAR_ENTRY)};

const gb_linear_backend *gb_linear_backend_of(int kind)
{
    for (size_t k = 0; k < sizeof BACKENDS / sizeof BACKENDS[0]; k++)
        if ((int)BACKENDS[k]->kind == kind) return BACKENDS[k];
    return NULL;
}

int gb_linear_symmetric(const gb_linear_backend *b, const gb_solver_settings *set)
{
    return b->symmetry == GB_SYMMETRIC || (b->symmetry == GB_SYMMETRIC_IF_DAMPED && set->newton != GB_NEWTON_LINE_SEARCH);
}
