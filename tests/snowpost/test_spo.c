/* test_spo.c - the statistics by origin of libsnowpost (spo_origin.h): known
 * answers worked by hand (three origins, one with two records; an origin in two
 * bins; an empty bin; the sub-bins), the empty and refused inputs, the mass
 * kept, and the result independent of the records' order. The masses are
 * multiples of 1/8, so that every sum is exact whatever its order. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "spo_origin.h"

#include <stdlib.h>
#include <string.h>

/* exact equality of doubles, shown in full when it fails (cmocka 1.1 compares as float) */
#define assert_exact(a, b)                                                                       \
    do {                                                                                         \
        const double a_ = (a), b_ = (b);                                                         \
        if (a_ != b_)                                                                            \
            fail_msg("%s = %.17g, expected %.17g", #a, a_, b_);                                 \
    } while (0)

static void assert_bin(const spo_bin *b, long n, long origins, double mass, double s2)
{
    assert_int_equal(b->n, n);
    assert_int_equal(b->origins, origins);
    assert_exact(b->mass, mass);
    assert_exact(b->s2, s2);
}

static void assert_zero_bin(const spo_bin *b)
{
    assert_bin(b, 0, 0, 0, 0);
    for (int s = 0; s < SPO_NSUB; s++) {
        assert_exact(b->sub_mass[s], 0);
        assert_exact(b->sub_s2[s], 0);
    }
}

/* one bin, origins 0:1 (1 + 2 kg), 0:2 (1 kg), 1:1 (2 kg): n 4, 3 origins,
   M = 6, S2 = 9 + 1 + 4 = 14, n_eff = 36 / 14 */
static void three_origins(void **state)
{
    (void)state;
    spo_record r[] = {{0, 0, 0, 1, 1.0}, {0, 0, 1, 1, 2.0}, {0, 0, 0, 2, 1.0}, {0, 0, 0, 1, 2.0}};
    spo_bin b;
    assert_int_equal(spo_origin_bins(r, 4, 1, &b, NULL, 0), SPO_OK);
    assert_bin(&b, 4, 3, 6, 14);
    assert_exact(spo_neff(&b), 36.0 / 14.0);
    /* the records sorted by (bin, proc, id) */
    for (int i = 0; i < 3; i++)
        assert_true(r[i].proc < r[i + 1].proc ||
                    (r[i].proc == r[i + 1].proc && r[i].id <= r[i + 1].id));
    /* the sub-bins unused: everything in sub-bin 0 */
    assert_exact(b.sub_mass[0], 6);
    assert_exact(b.sub_s2[0], 14);
    assert_exact(b.sub_mass[1], 0);
    assert_exact(b.sub_s2[1], 0);
}

/* an origin with records in two bins counts once in each */
static void origin_in_two_bins(void **state)
{
    (void)state;
    spo_record r[] = {{1, 0, 3, 4, 0.5}, {0, 0, 3, 4, 1.5}, {1, 0, 3, 4, 0.25}, {0, 0, 2, 9, 1.0}};
    spo_bin b[2];
    assert_int_equal(spo_origin_bins(r, 4, 2, b, NULL, 0), SPO_OK);
    assert_bin(&b[0], 2, 2, 2.5, 1.5 * 1.5 + 1.0);
    assert_bin(&b[1], 2, 1, 0.75, 0.75 * 0.75);
    assert_exact(spo_neff(&b[1]), 1);
}

/* three bins, the middle one without a record: all of it 0, n_eff 0 */
static void empty_bin(void **state)
{
    (void)state;
    spo_record r[] = {{2, 0, 0, 1, 1.0}, {0, 0, 0, 1, 1.0}, {2, 0, 0, 2, 3.0}};
    spo_bin b[3];
    memset(b, 0xff, sizeof b);
    assert_int_equal(spo_origin_bins(r, 3, 3, b, NULL, 0), SPO_OK);
    assert_bin(&b[0], 1, 1, 1, 1);
    assert_zero_bin(&b[1]);
    assert_exact(spo_neff(&b[1]), 0);
    assert_bin(&b[2], 2, 2, 4, 10);
    assert_exact(spo_neff(&b[2]), 1.6);
}

/* the sub-bins (the halves of a window): origin 0:1 with 1 kg in the first half
   and 2 + 1 kg in the second, 0:2 with 2 kg in the first: W = 4, 2 (S2 20);
   halves 1 + 2 = 3 (S2 1 + 4 = 5) and 3 + 0 = 3 (S2 9) */
static void sub_bins(void **state)
{
    (void)state;
    spo_record r[] = {{0, 1, 0, 1, 2.0}, {0, 0, 0, 2, 2.0}, {0, 0, 0, 1, 1.0}, {0, 1, 0, 1, 1.0}};
    spo_bin b;
    assert_int_equal(spo_origin_bins(r, 4, 1, &b, NULL, 0), SPO_OK);
    assert_bin(&b, 4, 2, 6, 20);
    assert_exact(b.sub_mass[0], 3);
    assert_exact(b.sub_s2[0], 5);
    assert_exact(b.sub_mass[1], 3);
    assert_exact(b.sub_s2[1], 9);
}

/* no record: every bin 0, with or without an array */
static void empty_input(void **state)
{
    (void)state;
    spo_record r[1] = {{0, 0, 5, 5, 1.0}};
    spo_bin b[2];
    memset(b, 0xff, sizeof b);
    assert_int_equal(spo_origin_bins(r, 0, 2, b, NULL, 0), SPO_OK);
    assert_zero_bin(&b[0]);
    assert_zero_bin(&b[1]);
    assert_int_equal(r[0].proc, 5); /* untouched */
    memset(b, 0xff, sizeof b);
    assert_int_equal(spo_origin_bins(NULL, 0, 2, b, NULL, 0), SPO_OK);
    assert_zero_bin(&b[0]);
    assert_zero_bin(&b[1]);
    assert_exact(spo_neff(&b[0]), 0);
}

/* refused: a message, the records and the bins as they were */
static void refused(void **state)
{
    (void)state;
    char err[128];
    spo_record r[] = {{1, 0, 9, 9, 1.0}, {0, 0, 1, 1, 1.0}};
    spo_bin b[2], was[2];
    memset(b, 0x5a, sizeof b);
    memcpy(was, b, sizeof b);
    err[0] = '\0';
    assert_int_equal(spo_origin_bins(NULL, 2, 2, b, err, sizeof err), SPO_EINVAL);
    assert_non_null(strstr(err, "no array"));
    assert_int_equal(spo_origin_bins(r, 2, 2, NULL, err, sizeof err), SPO_EINVAL);
    assert_int_equal(spo_origin_bins(r, 2, 0, b, err, sizeof err), SPO_EINVAL);
    assert_non_null(strstr(err, "0 bins"));
    assert_int_equal(spo_origin_bins(r, 2, 1, b, err, sizeof err), SPO_EINVAL);
    assert_string_equal(err, "record 1: bin 1 is not 0 .. 0");
    r[1].sub = SPO_NSUB;
    assert_int_equal(spo_origin_bins(r, 2, 2, b, err, sizeof err), SPO_EINVAL);
    assert_non_null(strstr(err, "record 2: sub-bin"));
    r[1].sub = -1;
    assert_int_equal(spo_origin_bins(r, 2, 2, b, NULL, 0), SPO_EINVAL);
    assert_memory_equal(b, was, sizeof b);
    assert_int_equal(r[0].bin, 1); /* not sorted */
    assert_int_equal(r[0].proc, 9);
}

/* many records, shuffled: the same statistics whatever the order, and every
   record's mass kept (in its bin and its sub-bins) */
enum { NREC = 2000, NBIN = 7 };

static void make(spo_record *r, unsigned seed)
{
    srand(seed);
    for (int i = 0; i < NREC; i++)
        r[i] = (spo_record){rand() % NBIN, rand() % 2, rand() % 3, rand() % 40,
                            (double)(1 + rand() % 64) / 8};
}

static void shuffle(spo_record *r, unsigned seed)
{
    srand(seed);
    for (int i = NREC - 1; i > 0; i--) {
        const int j = rand() % (i + 1);
        const spo_record t = r[i];
        r[i] = r[j];
        r[j] = t;
    }
}

static void order_and_mass(void **state)
{
    (void)state;
    static spo_record r[NREC], s[NREC];
    spo_bin a[NBIN], b[NBIN];
    make(r, 17);
    double total = 0, in_bin[NBIN] = {0};
    for (int i = 0; i < NREC; i++) {
        total += r[i].mass;
        in_bin[r[i].bin] += r[i].mass;
    }
    memcpy(s, r, sizeof r);
    assert_int_equal(spo_origin_bins(r, NREC, NBIN, a, NULL, 0), SPO_OK);
    double got = 0;
    long n = 0;
    for (int k = 0; k < NBIN; k++) {
        assert_exact(a[k].mass, in_bin[k]);
        assert_exact(a[k].sub_mass[0] + a[k].sub_mass[1], a[k].mass);
        assert_true(a[k].origins <= 3 * 40 && a[k].origins <= a[k].n);
        /* S2 lies between M^2 / origins (equal origins) and M^2 (one origin) */
        assert_true(a[k].s2 * (double)a[k].origins >= a[k].mass * a[k].mass);
        assert_true(a[k].s2 <= a[k].mass * a[k].mass);
        got += a[k].mass;
        n += a[k].n;
    }
    assert_exact(got, total);
    assert_int_equal(n, NREC);
    for (unsigned seed = 1; seed <= 5; seed++) {
        shuffle(s, seed);
        assert_int_equal(spo_origin_bins(s, NREC, NBIN, b, NULL, 0), SPO_OK);
        for (int k = 0; k < NBIN; k++) {
            assert_bin(&b[k], a[k].n, a[k].origins, a[k].mass, a[k].s2);
            for (int h = 0; h < SPO_NSUB; h++) {
                assert_exact(b[k].sub_mass[h], a[k].sub_mass[h]);
                assert_exact(b[k].sub_s2[h], a[k].sub_s2[h]);
            }
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(three_origins),  cmocka_unit_test(origin_in_two_bins),
        cmocka_unit_test(empty_bin),      cmocka_unit_test(sub_bins),
        cmocka_unit_test(empty_input),    cmocka_unit_test(refused),
        cmocka_unit_test(order_and_mass),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
