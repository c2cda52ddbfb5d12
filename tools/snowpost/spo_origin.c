/* spo_origin.c - the sampling statistics of a deposit by origin (spo_origin.h). */
#include "spo_origin.h"

#include "swo_err.h"

#include <stdlib.h>
#include <string.h>

/* by (bin, proc, id); the sub-bin and the mass do not order */
static int by_bin_origin(const void *pa, const void *pb)
{
    const spo_record *a = pa, *b = pb;
    if (a->bin != b->bin)
        return a->bin < b->bin ? -1 : 1;
    if (a->proc != b->proc)
        return a->proc < b->proc ? -1 : 1;
    if (a->id != b->id)
        return a->id < b->id ? -1 : 1;
    return 0;
}

int spo_origin_bins(spo_record *rec, size_t n, int nbin, spo_bin *out, char *err, size_t errlen)
{
    if (nbin < 1)
        return swo_fail(SPO_EINVAL, err, errlen, "%d bins: at least 1 is needed", nbin);
    if (!out)
        return swo_fail(SPO_EINVAL, err, errlen, "no array for the bins' statistics");
    if (n && !rec)
        return swo_fail(SPO_EINVAL, err, errlen, "%zu records but no array of them", n);
    for (size_t i = 0; i < n; i++) {
        if (rec[i].bin < 0 || rec[i].bin >= nbin)
            return swo_fail(SPO_EINVAL, err, errlen, "record %zu: bin %d is not 0 .. %d", i + 1,
                            rec[i].bin, nbin - 1);
        if (rec[i].sub < 0 || rec[i].sub >= SPO_NSUB)
            return swo_fail(SPO_EINVAL, err, errlen, "record %zu: sub-bin %d is not 0 .. %d", i + 1,
                            rec[i].sub, SPO_NSUB - 1);
    }
    memset(out, 0, (size_t)nbin * sizeof *out);
    if (n == 0)
        return SPO_OK;
    qsort(rec, n, sizeof *rec, by_bin_origin);
    for (size_t i = 0; i < n;) {
        /* origin a: its records rec[i .. j) */
        double wa = 0, ws[SPO_NSUB] = {0};
        size_t j = i;
        for (; j < n && by_bin_origin(rec + i, rec + j) == 0; j++) {
            wa += rec[j].mass;
            ws[rec[j].sub] += rec[j].mass;
        }
        spo_bin *b = &out[rec[i].bin];
        b->n += (long)(j - i);
        b->origins++;
        b->mass += wa;
        b->s2 += wa * wa;
        for (int s = 0; s < SPO_NSUB; s++) {
            b->sub_mass[s] += ws[s];
            b->sub_s2[s] += ws[s] * ws[s];
        }
        i = j;
    }
    return SPO_OK;
}

double spo_neff(const spo_bin *b)
{
    return (b->s2 > 0) ? b->mass * b->mass / b->s2 : 0;
}
