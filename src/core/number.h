/* Numbers: reading one written by gembem (or a user) back exactly; a median. */
#ifndef GB_CORE_NUMBER_H
#define GB_CORE_NUMBER_H

typedef enum { GB_NUMBER_OK, GB_NUMBER_SYNTAX, GB_NUMBER_INFINITE } gb_number_result;

/* The whole of s as a finite double. A value below DBL_MIN is accepted as the subnormal (or zero)
 * strtod returns: %.17g writes such values (a tangential force of 8.8e-317 in a state file), and
 * they must read back; only overflow, inf and nan are refused. */
gb_number_result gb_parse_finite(const char *s, double *out);

/* The median of v[0 .. n) (0 for n = 0), sorting v in place. */
double gb_median(double *v, int n);

#endif
