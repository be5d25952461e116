/* The processes of the PETSc linear solver (solver.linear: petsc, docs/scaling.md).
 * gembem is a serial program: under `mpirun -np P`, rank 0 runs it and the other ranks only take
 * part in the global solver's linear solves (a host and its workers, as MUMPS itself works). */
#ifndef GEMBEM_PETSC_H
#define GEMBEM_PETSC_H

/* 1 if this gembem was built with PETSc, else 0. */
int gb_petsc_available(void);

/* The MPI processes taking part in the solves (1 without a launcher or without PETSc). */
int gb_petsc_ranks(void);

/* Call first in main. Launched by mpirun (or another MPI launcher), it starts MPI and PETSc on
 * every rank; a rank other than 0 then serves rank 0's linear solves until rank 0 ends, and
 * returns 1 with the code the process should exit with in *code. Returns 0 on rank 0, without a
 * launcher (PETSc then starts on the first solve, in one process) and without PETSc. Rank 0's
 * end (return from main or exit) stops the workers and PETSc. */
int gb_petsc_serve(int *code);

#endif
