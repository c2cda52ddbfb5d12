/* fuzz_coeffs.c - libFuzzer target: the wall model's regime.coeffs reader.
 *
 * Any bytes as a coefficients file: sww_regime_load must return SWW_OK or a
 * negative code with a message (no crash, no sanitizer report, no hang); a
 * file that loads must decide impacts over the whole input range without NaN
 * (sww_decide, the gates on and off, the probability table if present) and
 * describe itself. Built by tests/fuzz/run.sh; replayed over the corpus in
 * every test build (fuzz_replay.c). */
#include "fuzz_input.h"   /* first: it defines _GNU_SOURCE for memfd_create */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "sww.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[64];
    int fd;
    if (!fuzz_file(data, size, &fd, path, sizeof path))
        return 0;
    sww_model *m = sww_alloc();
    if (!m) {
        close(fd);
        return 0;
    }
    const int rc = sww_regime_load(m, path);
    close(fd);
    if (rc != SWW_OK) {
        if (!sww_errmsg(m)[0] || strchr(sww_errmsg(m), '\n'))
            __builtin_trap(); /* a failure names itself on one line */
        sww_free(m);
        return 0;
    }
    char buf[1024];
    sww_describe(m, buf, sizeof buf);
    static const double ds[] = { 1e-7, 1e-5, 5e-5, 1e-4, 1e-2 };
    static const double vs[] = { 0.0, 1e-3, 0.3, 3.0, 30.0, 1e3 };
    for (int gate = 0; gate < 3; gate++) {
        if (gate == 1)
            sww_set_tangential_gate(m, 0.5, 5e-5, -0.5);
        if (gate == 2 && sww_set_shear_gate_adhesion(m, 0.5) != SWW_OK)
            sww_set_shear_gate_constant(m, 1.0);
        for (size_t i = 0; i < sizeof ds / sizeof *ds; i++)
            for (size_t j = 0; j < sizeof vs / sizeof *vs; j++) {
                sww_impact in = { ds[i], vs[j], vs[(j + 1) % 6], 0.5, 0.37 };
                sww_outcome o;
                if (sww_decide(m, &in, &o) == SWW_OK
                    && (isnan(o.p_stick) || isnan(o.e_n) || isnan(o.e_t) || isnan(o.d_crit)))
                    __builtin_trap(); /* a decision is never NaN */
            }
    }
    sww_free(m);
    return 0;
}
