/* kernel_test.h - settings and models from "key=value" lists, for the kernel's
 * cmocka tests (a bad key fails the test with the kernel's message). */
#ifndef KERNEL_TEST_H
#define KERNEL_TEST_H

#include "swr_collide.h"

static inline swr_params test_params(const char *const *kv)
{
    swr_params p;
    swr_params_default(&p);
    char err[256];
    for (; kv && *kv; kv++)
        if (swr_params_set_kv(&p, *kv, err, sizeof err) != 0)
            fail_msg("%s", err);
    return p;
}

static inline swr_model *test_model(const char *const *kv)
{
    swr_params p = test_params(kv);
    char err[256];
    swr_model *m = swr_model_alloc(&p, err, sizeof err);
    if (!m)
        fail_msg("%s", err);
    return m;
}

#endif
