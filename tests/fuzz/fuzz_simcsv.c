/* fuzz_simcsv.c - libFuzzer target: snowphoto's simulated-map CSV reader
 * (swi_simmap_read_mem, tools/snowphoto/swi_compare.c; the rear_deposit.csv that
 * tutorials/wedge/post/wedge-post writes).
 *
 * Any bytes as the CSV: 0 with a full regular grid of finite values >= 0 that
 * can be sampled, or an error code with one line in err (no crash, no
 * sanitizer report, no hang). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "swi_compare.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    swi_simmap *m = NULL;
    char err[300];
    const int rc = swi_simmap_read_mem((const char *)data, size, "fuzz", &m, err, sizeof err);
    if (rc != 0) {
        if (m || !err[0] || strchr(err, '\n'))
            __builtin_trap();
        return 0;
    }
    if (!m || m->ny < 2 || m->nz < 2)
        __builtin_trap();
    for (int k = 0; k < 9; k++) {
        const double u = m->y0 + (m->y1 - m->y0) * (k % 3) / 2.0;
        const double v = m->z0 + (m->z1 - m->z0) * (k / 3) / 2.0;
        const double x = swi_simmap_at(m, u, v);
        if (!(x >= 0.0) || isinf(x))
            __builtin_trap(); /* values are finite and >= 0 */
    }
    swi_simmap_free(m);
    return 0;
}
