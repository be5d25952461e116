/* The random numbers of the packings (gembem pack, gb_packgen): xoshiro256** seeded by splitmix64.
 *
 * Both generators are by David Blackman and Sebastiano Vigna (public domain reference code at
 * https://prng.di.unimi.it/). Only 64-bit integer arithmetic is used, so a seed gives the same
 * stream on every machine and compiler. The state is a value passed around: no globals. */
#ifndef GEMBEM_RNG_H
#define GEMBEM_RNG_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    uint64_t s[4];
} gb_rng;

/* splitmix64: one step of the seeding generator; advances *x. */
static inline uint64_t gb_splitmix64(uint64_t *x)
{
    uint64_t z = (*x += UINT64_C(0x9E3779B97F4A7C15));
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

/* Seed from (seed, stream): distinct streams give independent sequences for one seed. */
static inline void gb_rng_seed(gb_rng *r, uint64_t seed, uint64_t stream)
{
    uint64_t x = seed ^ (stream * UINT64_C(0xD1B54A32D192ED03));
    for (int i = 0; i < 4; ++i)
        r->s[i] = gb_splitmix64(&x);
}

static inline uint64_t gb_rotl(uint64_t x, int k)
{
    return (x << k) | (x >> (64 - k));
}

/* xoshiro256**: next 64 random bits. */
static inline uint64_t gb_rng_next(gb_rng *r)
{
    uint64_t *s = r->s;
    const uint64_t result = gb_rotl(s[1] * 5, 7) * 9;
    const uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = gb_rotl(s[3], 45);
    return result;
}

/* Uniform double in [0, 1): the top 53 bits, exactly representable. */
static inline double gb_rng_uniform(gb_rng *r)
{
    return (double)(gb_rng_next(r) >> 11) * (1.0 / 9007199254740992.0);
}

/* Uniform integer in [0, n), n >= 1, without modulo bias (rejection). */
static inline size_t gb_rng_below(gb_rng *r, size_t n)
{
    const uint64_t m = (uint64_t)n;
    const uint64_t limit = UINT64_MAX - UINT64_MAX % m;
    uint64_t x;
    do
        x = gb_rng_next(r);
    while (x >= limit);
    return (size_t)(x % m);
}

#endif
