/* swi_error.h - the photo comparison's error reporting (internal). */
#ifndef SWI_ERROR_H
#define SWI_ERROR_H

#include <stddef.h>

/* Format a one-line message into err (when err and errlen are given) and
 * return code, so that a failing function can `return swi_fail(...)`. */
int swi_fail(char *err, size_t errlen, int code, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

#endif
