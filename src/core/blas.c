#include "core/blas.h"

#include <cblas.h>

int gb_blas_single(void)
{
    int t = openblas_get_num_threads();
    if (t > 1) openblas_set_num_threads(1);
    return t;
}

void gb_blas_restore(int threads)
{
    if (threads > 1) openblas_set_num_threads(threads);
}
