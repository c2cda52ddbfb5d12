/* sww_draw.c - the uniform numbers of the stick draws (see sww.h): a
 * counter-based hash of a seed and four integers (SplitMix64's finaliser),
 * the same on every machine, processor and thread. */
#include "sww_internal.h"

static unsigned long long mix64(unsigned long long z)
{
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

double sww_uniform_hash(unsigned long long seed, long long a, long long b, long long c,
                        long long k)
{
    unsigned long long h = mix64(seed);
    h = mix64(h ^ (unsigned long long)a);
    h = mix64(h ^ (unsigned long long)b);
    h = mix64(h ^ (unsigned long long)c);
    h = mix64(h ^ (unsigned long long)k);
    return (double)(h >> 11) * 0x1.0p-53; /* [0, 1 - 2^-53] */
}
