/* swv_error.h - the validation module's error reporting (internal). */
#ifndef SWV_ERROR_H
#define SWV_ERROR_H

#include <stddef.h>

/* Format a one-line message into err (when err and errlen are given) and
 * return code, so that a failing function can `return swv_fail(...)`. */
int swv_fail(char *err, size_t errlen, int code, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

#endif
