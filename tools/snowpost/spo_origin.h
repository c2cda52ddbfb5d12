/* spo_origin.h - the sampling statistics of a deposit "by origin": records of
 * mass that stuck, grouped per bin by the parcel they came from.
 * libsnowpost (prefix spo_) is where the case tools' case-neutral post-processing is to move.
 *
 * A record is a mass [kg] that stuck, its origin (proc, id): the injected
 * parcel it came from (the copies a parcel splitting makes share their
 * origin), and a bin: whatever the caller sums over (a region of a face, a
 * block of a grid, a time window). Per bin b, with W_a the summed mass of
 * origin a's records in b:
 *
 *   n        the records in b
 *   origins  the distinct origins in b
 *   M        = sum_a W_a, the bin's mass [kg]
 *   S2       = sum_a W_a^2 [kg^2]
 *
 * Assuming the origins independent (each injected parcel's fate independent
 * of the others', its copies not), M is a sum of independent terms: its
 * variance is estimated by S2, its effective sample size is
 * n_eff = M^2 / S2 (spo_neff) and its relative standard error 1 / sqrt(n_eff).
 * Records of one origin are not independent and count once.
 *
 * A record may also carry a sub-bin s (0 .. SPO_NSUB - 1, 0 when unused): a
 * second split of each origin's mass within its bin (the two halves of a
 * time window); per bin and sub-bin sub_mass[s] = sum_a W_a,s and
 * sub_s2[s] = sum_a W_a,s^2, W_a,s the mass of origin a's records in b and s.
 * The sub-bin does not order the records.
 *
 * The order of the sums, which their last bits depend on: the records are
 * sorted by (bin, proc, id) with qsort (records of one origin in one bin
 * in qsort's order, which is not stable), each origin's W_a and W_a,s are
 * summed in that order, and the origins are added to their bin in
 * (proc, id) order. Masses are summed as given (the caller checks them).
 *
 * Plain functions on the caller's arrays: no state, no allocation, nothing
 * printed, never an exit; no threads (distinct arrays may be used from
 * distinct threads). Errors: a negative code and a one-line message in err
 * (common/swo_err.h). */
#ifndef SPO_ORIGIN_H
#define SPO_ORIGIN_H

#include <stddef.h>

enum { SPO_OK = 0, SPO_EINVAL = -1 };

/* the sub-bins of a bin */
#define SPO_NSUB 2

/* one record */
typedef struct {
    int bin;       /* 0 .. nbin - 1 */
    int sub;       /* 0 .. SPO_NSUB - 1 (0 when unused) */
    long proc, id; /* its origin */
    double mass;   /* [kg] */
} spo_record;

/* a bin's statistics */
typedef struct {
    long n;                    /* records */
    long origins;              /* distinct origins */
    double mass;               /* M = sum_a W_a [kg] */
    double s2;                 /* S2 = sum_a W_a^2 [kg^2] */
    double sub_mass[SPO_NSUB]; /* sum_a W_a,s [kg] */
    double sub_s2[SPO_NSUB];   /* sum_a W_a,s^2 [kg^2] */
} spo_bin;

/* the statistics of every bin (out[nbin], zeroed first; a bin without a
   record stays 0) of the n records rec, which are sorted in place by
   (bin, proc, id). rec may be NULL when n is 0. 0, or SPO_EINVAL with a
   message in err (nbin < 1, out NULL, rec NULL with n > 0, a record's bin
   or sub-bin out of range; then rec and out are left as they were). */
int spo_origin_bins(spo_record *rec, size_t n, int nbin, spo_bin *out, char *err, size_t errlen);

/* the effective sample size M^2 / S2 of a bin; 0 unless S2 > 0 (no record,
   or no mass) */
double spo_neff(const spo_bin *b);

#endif
