/* One BLAS thread around the calls whose rounding depends on OpenBLAS's thread count. */
#ifndef GB_CORE_BLAS_H
#define GB_CORE_BLAS_H

/* OpenBLAS splits some operations by its thread count and sums the parts in another order: dgetrf's
 * panels, and a dgemv whose rows are few for its columns is split by columns and the partial
 * vectors added. A run would then give other bytes with OPENBLAS_NUM_THREADS=1 than 2 (a hybrid
 * run's grains by up to 6e-3 of a radius). gb_blas_single sets one thread and returns the count it
 * replaced, gb_blas_restore puts it back. */
int gb_blas_single(void);
void gb_blas_restore(int threads);

#endif
